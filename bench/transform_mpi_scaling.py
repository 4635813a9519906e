#!/usr/bin/python3
"""Weak scaling of `zdg transform dt --mpi` and a model of its communication (issue #15, 3).

Weak scaling: for P = 1, 2, 4 ranks (--ranks), the same voxels per rank: a volume of
P x SLICES slices of N x N (uint8 .npy; an ellipsoid of semi-axes 0.45 x the extents, so that
the work per voxel does not change with P), transformed by

  mpiexec -np P zdg transform dt IN.npy -o OUT.npy --mpi --threads T --json --quiet

Prints, per P, the wall time of the whole job (launch, read, transform, exchange, write) and
the slowest rank's time in each stage (from zdg's JSON), the efficiency t(1) / t(P), and checks
the output against the single-process command's, byte for byte. On a machine with fewer cores
than P x T the ranks share cores: the efficiency then measures the oversubscription too.

  /usr/bin/python3 bench/transform_mpi_scaling.py --zdg build/bin/zdg --n 256 --slices 128

--model prints the communication of the transpose for a 2048^3 volume (l2: int32 values in
flight; 8 more bytes per voxel for a Voronoi map) on 8, 64 and 512 ranks: the bytes every
rank sends, the size of each pairwise message, and the time at a given per-rank bandwidth.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def ellipsoid(nz, n):
    z, y, x = np.ogrid[:nz, :n, :n]
    cz, c = (nz - 1) / 2.0, (n - 1) / 2.0
    rz, r = 0.45 * nz, 0.45 * n
    return (((x - c) / r) ** 2 + ((y - c) / r) ** 2 + ((z - cz) / rz) ** 2 < 1).astype(np.uint8)


def model(bandwidth_gbs):
    n = 2048 ** 3
    print(f"Transpose of a 2048^3 volume (N = {n:.3e} voxels), l2 (int32 values in flight):")
    print("| ranks | slab per rank | sent per rank | message per pair | total exchanged |"
          f" time at {bandwidth_gbs:g} GB/s per rank |")
    print("|---|---|---|---|---|---|")
    for p in (8, 64, 512):
        value = 4
        per_rank = n * value * (p - 1) / p / p
        pair = n * value / (p * p)
        total = n * value * (p - 1) / p
        print(f"| {p} | {n * value / p / 2**30:.2f} GiB | {per_rank / 2**30:.3f} GiB |"
              f" {pair / 2**20:.3f} MiB | {total / 2**30:.1f} GiB |"
              f" {per_rank / (bandwidth_gbs * 1e9):.3f} s |")
    print("A Voronoi map moves 8 more bytes per voxel (the site's index): x3 the bytes. Messages"
          " per rank: P - 1 (pairwise rounds); reads and writes: N/P bytes in, N/P x 4 out.")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--zdg", default="build/bin/zdg")
    ap.add_argument("--mpiexec", default="mpiexec")
    ap.add_argument("--n", type=int, default=256, help="slice side")
    ap.add_argument("--slices", type=int, default=128, help="slices per rank")
    ap.add_argument("--ranks", default="1,2,4")
    ap.add_argument("--threads", type=int, default=1, help="threads per rank")
    ap.add_argument("--runs", type=int, default=2, help="best of")
    ap.add_argument("--model", action="store_true")
    ap.add_argument("--bandwidth", type=float, default=12.5, help="GB/s per rank, for --model")
    a = ap.parse_args()
    if a.model:
        model(a.bandwidth)
        return 0
    env = dict(os.environ)
    if os.geteuid() == 0:  # OpenMPI refuses root unless told (containers, CI)
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for p in [int(x) for x in a.ranks.split(",")]:
            src, out, ref = (os.path.join(tmp, f) for f in ("in.npy", "out.npy", "ref.npy"))
            np.save(src, ellipsoid(p * a.slices, a.n))
            subprocess.run([a.zdg, "transform", "dt", src, "-o", ref, "--force", "--quiet",
                            "--threads", str(a.threads)], check=True, capture_output=True)
            best = None
            for _ in range(a.runs):
                t0 = time.perf_counter()
                r = subprocess.run([a.mpiexec, "-np", str(p), "--oversubscribe", a.zdg,
                                    "transform", "dt", src, "-o", out, "--mpi", "--force",
                                    "--quiet", "--json", "--threads", str(a.threads)],
                                   env=env, capture_output=True, text=True)
                wall = time.perf_counter() - t0
                if r.returncode != 0:
                    sys.exit(f"mpiexec -np {p}: exit {r.returncode}: {r.stderr.strip()}")
                if best is None or wall < best[0]:
                    best = (wall, json.loads(r.stdout))
            with open(out, "rb") as f1, open(ref, "rb") as f2:
                same = f1.read() == f2.read()
            rows.append((p, best[0], best[1], same))
    t1 = rows[0][1]
    print(f"Weak scaling, {a.slices} slices of {a.n}^2 per rank ({a.slices * a.n * a.n / 1e6:.1f}"
          f" M voxels), l2, {a.threads} thread(s) per rank, {os.cpu_count()} cores; best of"
          f" {a.runs}:")
    print("| P | shape | wall s | read | slab passes | exchange | axis 0 | write | t(1)/t(P) |"
          " = single process |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for p, wall, j, same in rows:
        s = j["stages"]
        shape = "x".join(str(e) for e in j["shape"])
        print(f"| {p} | {shape} | {wall:.2f} | {s['read']:.2f} | {s['slab passes']:.2f} |"
              f" {s['exchange']:.2f} | {s['axis 0']:.2f} | {s['write']:.2f} | {t1 / wall:.2f} |"
              f" {'yes' if same else 'NO'} |")
    return 0 if all(r[3] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
