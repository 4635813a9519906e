#!/usr/bin/python3
"""Times zdg's cubical persistence against GUDHI's on the same array, in one run (#39 item 5).

Input: smoothed Gaussian noise, n^3 float32 (numpy seed 7, scipy.ndimage.gaussian_filter with
sigma 2), n = 256 by default. zdg runs through `zdg topology persistence IN.npy --json` and
reports its own compute time ("seconds": the diagrams, file IO excluded) beside the command's
wall time; GUDHI is timed in-process: gudhi.CubicalComplex(top_dimensional_cells=a)
.persistence() on the same values as float64 (its construction included). The diagrams are
checked equal, number for number. Prints the seconds and the ratio GUDHI / zdg (> 1: zdg is
faster).

  /usr/bin/python3 bench/compare_persistence.py --zdg build/bin/zdg [--n 256]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def noise(n):
    from scipy import ndimage

    rng = np.random.default_rng(7)
    return ndimage.gaussian_filter(rng.normal(size=(n, n, n)), 2.0).astype(np.float32)


def key(p):
    return (p[0], float("inf") if p[1] is None else p[1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--zdg", default="build/bin/zdg")
    ap.add_argument("--n", type=int, default=256)
    args = ap.parse_args()
    import gudhi

    a = noise(args.n)
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "noise.npy")
        np.save(path, a)
        t = time.perf_counter()
        out = subprocess.run([args.zdg, "topology", "persistence", path, "--json", "--quiet"],
                             check=True, capture_output=True, text=True).stdout
        zdg_wall = time.perf_counter() - t
    z = json.loads(out)
    t = time.perf_counter()
    cc = gudhi.CubicalComplex(top_dimensional_cells=a.astype(np.float64))
    cc.persistence()
    gudhi_s = time.perf_counter() - t
    same = True
    for k, pairs in enumerate(z["diagrams"]):
        mine = sorted(((float(b), None if d is None else float(d)) for b, d in pairs), key=key)
        theirs = sorted(((float(b), None if np.isinf(d) else float(d))
                         for b, d in cc.persistence_intervals_in_dimension(k)), key=key)
        same = same and mine == theirs
        print(f"dimension {k}: {len(mine)} pairs (GUDHI {len(theirs)})")
    print(f"{args.n}^3 float32: zdg {z['seconds']:.2f} s (command {zdg_wall:.2f} s), "
          f"GUDHI {gudhi_s:.2f} s, ratio GUDHI / zdg {gudhi_s / z['seconds']:.1f} "
          f"({gudhi_s / zdg_wall:.1f} with the command's IO), diagrams equal: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
