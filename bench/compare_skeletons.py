#!/usr/bin/python3
"""Times zdg's curve skeleton against scikit-image's skeletonize (3D: Lee, Kashyap and Chu
1994) on the same foam-like volumes, in one run, and prints the ratio.

Volume: uniform noise (numpy default_rng, fixed seed) smoothed by three box blurs of size 7
(scipy.ndimage.uniform_filter, 'nearest' ends), thresholded at its 80th percentile: about 20%
of the voxels in the object, n^3 voxels (n = 256; 512 with --large). `--volume waves` takes
instead the volume of bench/surface_bench.cpp (the level set {f > 0} of 24 random plane waves
of wavelength 40 to 80 voxels, the same mt19937_64 draws and the same floating-point
operations, hence the same voxels; about half of them in the object), `--volume FILE.npy` a
user's volume.

zdg runs through `zdg topology skeleton IN.npy -o OUT.npy --json --quiet --threads T` and
reports its own compute time ("seconds": thinning, distance transform included, file IO
excluded); the process wall and CPU times are printed too (CPU time is the fair measure on a
shared machine). skimage is timed in-process (one thread, its only mode). Both skeletons are then measured by `zdg topology betti` (26,6): zdg's keeps the
Betti numbers of the object by construction; the line says whether skimage's does.

  /usr/bin/python3 bench/compare_skeletons.py --zdg build/bin/zdg [--large] [--threads 1,2]
  /usr/bin/python3 bench/compare_skeletons.py --volume waves --sizes 512
"""
import argparse
import contextlib
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy import ndimage


def foam(n, seed=20240613):
    rng = np.random.default_rng(seed)
    v = rng.random((n, n, n), dtype=np.float32)
    for _ in range(3):
        v = ndimage.uniform_filter(v, size=7, mode="nearest")
    t = np.percentile(v, 80)
    return (v > t).astype(np.uint8)


class MT19937_64:
    """std::mt19937_64 (the C++ standard's 64-bit Mersenne twister), for the few draws of the
    plane-wave volume."""

    def __init__(self, seed):
        self.mt = [seed & 0xFFFFFFFFFFFFFFFF]
        for i in range(1, 312):
            prev = self.mt[-1]
            self.mt.append((6364136223846793005 * (prev ^ (prev >> 62)) + i) & 0xFFFFFFFFFFFFFFFF)
        self.i = 312

    def __call__(self):
        if self.i >= 312:
            for k in range(312):
                y = (self.mt[k] & 0xFFFFFFFF80000000) | (self.mt[(k + 1) % 312] & 0x7FFFFFFF)
                v = self.mt[(k + 156) % 312] ^ (y >> 1)
                if y & 1:
                    v ^= 0xB5026F5AA96619E9
                self.mt[k] = v
            self.i = 0
        y = self.mt[self.i]
        self.i += 1
        y ^= (y >> 29) & 0x5555555555555555
        y ^= (y << 17) & 0x71D67FFFEDA60000
        y ^= (y << 37) & 0xFFF7EEE000000000
        y ^= y >> 43
        return y

    def uniform(self):
        # libstdc++'s generate_canonical<double, 53> on a 64-bit engine: one draw / 2^64.
        r = float(self()) / 18446744073709551616.0
        return r if r < 1.0 else np.nextafter(1.0, 0.0)


def waves(n, count=24, seed=12):
    """The volume of bench/surface_bench.cpp: f(x) = sum_k Re(e^{i(k.x + phi_k)}), the same
    products of per-axis exponentials in the same order, object = {f > 0}."""
    rng = MT19937_64(seed)
    i = np.arange(n, dtype=np.float64)
    ex, ey, ez = [], [], []
    for _ in range(count):
        lam = 40 + 40 * rng.uniform()
        th = np.arccos(2 * rng.uniform() - 1)
        ph = 2 * np.pi * rng.uniform()
        phase = 2 * np.pi * rng.uniform()
        k = 2 * np.pi / lam
        kx, ky, kz = k * np.sin(th) * np.cos(ph), k * np.sin(th) * np.sin(ph), k * np.cos(th)
        for e, arg in ((ex, kx * i + phase), (ey, ky * i), (ez, kz * i)):
            c = np.empty(n, dtype=np.complex128)  # std::polar(1.0, arg): (cos, sin)
            c.real, c.imag = np.cos(arg), np.sin(arg)
            e.append(c)
    out = np.empty((n, n, n), dtype=np.uint8)
    for z in range(n):
        f = np.zeros((n, n))
        for w in range(count):
            yz = ey[w][:, None] * ez[w][z]
            f += (ex[w][None, :] * yz).real
        out[z] = f > 0
    return out


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def zdg_json(zdg, args):
    t0, c0 = time.perf_counter(), children_cpu()
    out = subprocess.run([zdg] + args, check=True, capture_output=True, text=True)
    return json.loads(out.stdout), time.perf_counter() - t0, children_cpu() - c0


def betti(zdg, path):
    j, _, _ = zdg_json(zdg, ["topology", "betti", path, "--json"])
    return [int(b) for b in j["betti"]]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--zdg", default="build/bin/zdg")
    ap.add_argument("--large", action="store_true", help="also n = 512")
    ap.add_argument("--sizes", default=None, help="comma list of n (default 256, or 256,512)")
    ap.add_argument("--threads", default="1", help="comma list of thread counts for zdg")
    ap.add_argument("--critical", action="store_true", help="also --method critical-kernel")
    ap.add_argument("--no-skimage", action="store_true", help="zdg only")
    ap.add_argument("--volume", default="noise",
                    help="noise (default), waves (surface_bench's volume) or FILE.npy")
    ap.add_argument("--keep", default=None, help="folder where the volumes and skeletons stay")
    a = ap.parse_args()
    sizes = [int(s) for s in a.sizes.split(",")] if a.sizes else ([256, 512] if a.large else [256])
    threads = [int(t) for t in a.threads.split(",")]
    methods = ["sequential"] + (["critical-kernel"] if a.critical else [])
    from skimage.morphology import skeletonize

    if a.keep:
        os.makedirs(a.keep, exist_ok=True)
    with (contextlib.nullcontext(a.keep) if a.keep else tempfile.TemporaryDirectory()) as tmp:
        for n in sizes:
            if a.volume == "noise":
                img = foam(n)
            elif a.volume == "waves":
                img = waves(n)
            else:
                img = (np.load(a.volume) != 0).astype(np.uint8)
                n = round(img.size ** (1 / 3))
            src = os.path.join(tmp, "foam.npy")
            np.save(src, img)
            obj = int(img.sum())
            b_obj = betti(a.zdg, src)
            print(f"n={n}: {obj} object voxels ({100.0 * obj / img.size:.1f}%), Betti {b_obj}")
            zdg_best = None
            for method in methods:
                for t in threads:
                    dst = os.path.join(tmp, f"zdg_{method}_{t}.npy")
                    j, wall, cpu = zdg_json(a.zdg, ["topology", "skeleton", src, "-o", dst, "--json",
                                               "--quiet", "--force", "--threads", str(t),
                                               "--method", method])
                    secs = float(j["seconds"])
                    print(f"  zdg {method:15s} threads={t}: {secs:8.2f} s (process {wall:.2f} s, "
                          f"CPU {cpu:.2f} s), "
                          f"{j['voxels']} skeleton voxels, Betti {[int(x) for x in j['betti']]}")
                    if method == "sequential" and t == 1:
                        zdg_best, zdg_cpu = secs, cpu
            if a.no_skimage:
                continue
            t0, c0 = time.perf_counter(), time.process_time()
            sk = skeletonize(img)
            ski, ski_cpu = time.perf_counter() - t0, time.process_time() - c0
            skp = os.path.join(tmp, "skimage.npy")
            np.save(skp, (sk != 0).astype(np.uint8))
            b_sk = betti(a.zdg, skp)
            print(f"  skimage skeletonize (Lee)      : {ski:8.2f} s (CPU {ski_cpu:.2f} s), "
                  f"{int((sk != 0).sum())} "
                  f"skeleton voxels, Betti {b_sk}"
                  f"{'' if b_sk == b_obj else ' (topology changed)'}")
            if zdg_best:
                print(f"  ratio skimage / zdg sequential 1 thread: {ski / zdg_best:.2f} wall, "
                      f"{ski_cpu / zdg_cpu:.2f} CPU (zdg process, IO included)"
                      f" ({'zdg faster' if ski > zdg_best else 'skimage faster'})")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
