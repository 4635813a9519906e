#!/usr/bin/python3
"""Times zdg's exact distance transform against peers on the same inputs, in one run.

Inputs (issue 4): a disc of radius 1800 in 4096^2, a ball of radius 0.45 n in n^3 for
n = 256 (and 512 with --large). zdg runs through `zdg transform dt IN.npy -o OUT.npy --json`
and reports its own compute time ("seconds", file IO excluded); peers are timed in-process:
  scipy.ndimage.distance_transform_edt (1 thread, float64 Euclidean distance),
  OpenCV cv2.distanceTransform DIST_L2 DIST_MASK_PRECISE (2D only, cv2.setNumThreads),
  ITK SignedMaurerDistanceMapImageFilter (if the python module `itk` imports),
  seung-lab's edt, edt.edtsq (squared distances, float32, `parallel` = --threads; if the python
  module `edt` imports: it is on PyPI, or built from its source without network, e.g.
    cython3 -3 --cplus src/edt.pyx -o edt.cpp && g++ -shared -fPIC -std=c++17 -O3 -pthread \
      -Isrc -I$(python3 -c 'import sysconfig; print(sysconfig.get_paths()["include"])') \
      -I$(python3 -c 'import numpy; print(numpy.get_include())') edt.cpp -o edt$(python3-config --extension-suffix)
  then PYTHONPATH=that folder; Debian's cython3 is enough).
Each peer's result is checked against zdg's exact squared distances (round(d^2) == zdg).
Prints median seconds and the ratio peer / zdg (> 1: zdg is faster).

  /usr/bin/python3 bench/compare_transforms.py --zdg build/bin/zdg --threads 2 [--large]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np


def disc(n, r):
    y, x = np.ogrid[:n, :n]
    c = n // 2
    return ((x - c) ** 2 + (y - c) ** 2 < r * r).astype(np.uint8)


def ball(n):
    z, y, x = np.ogrid[:n, :n, :n]
    c, r = n // 2, (45 * n) // 100
    return ((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2 < r * r).astype(np.uint8)


def median_time(fn, repeats):
    times, out = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def run_zdg(zdg, img, threads, repeats, metric, tmp):
    src, dst = os.path.join(tmp, "in.npy"), os.path.join(tmp, "out.npy")
    np.save(src, img)
    times = []
    for _ in range(repeats):
        r = subprocess.run([zdg, "transform", "dt", src, "-o", dst, "--metric", metric,
                            "--threads", str(threads), "--json", "--force"],
                           capture_output=True, text=True, check=True)
        times.append(json.loads(r.stdout)["seconds"])
    return statistics.median(times), np.load(dst)


def peers(threads):
    out = {}
    try:
        import scipy.ndimage as ndi
        out["scipy"] = lambda img: ndi.distance_transform_edt(img)
    except ImportError:
        pass
    try:
        import cv2
        cv2.setNumThreads(threads)

        def opencv(img):
            if img.ndim != 2:
                return None
            return cv2.distanceTransform(img, cv2.DIST_L2, cv2.DIST_MASK_PRECISE)
        out["opencv"] = opencv
    except ImportError:
        pass
    try:
        import itk

        def itk_maurer(img):
            image = itk.image_from_array(img)
            f = itk.SignedMaurerDistanceMapImageFilter.New(image)
            f.SetSquaredDistance(False)
            f.SetUseImageSpacing(False)
            f.SetInsideIsPositive(True)
            f.SetNumberOfWorkUnits(threads)
            f.Update()
            return itk.array_from_image(f.GetOutput())
        out["itk"] = itk_maurer
    except ImportError:
        pass
    try:
        import edt

        def seung_lab_edt(img):
            # Squared distances to the nearest 0 (labels other than 0 are one object here: the
            # masks are 0/1); no border of zeros around the image, as for the others.
            return edt.edtsq(img, black_border=False, parallel=threads)
        out["edt"] = seung_lab_edt
    except ImportError:
        pass
    return out


# Peers whose values are squared distances already.
SQUARED = {"edt"}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--zdg", default="build/bin/zdg")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--large", action="store_true", help="also 3D 512^3 (zdg only by default)")
    ap.add_argument("--quick", action="store_true", help="small inputs (a smoke test)")
    args = ap.parse_args()
    inputs = [("2D 4096^2 disc r=1800", lambda: disc(4096, 1800)), ("3D 256^3 ball r=0.45n", lambda: ball(256))]
    if args.quick:
        inputs = [("2D 512^2 disc r=225", lambda: disc(512, 225)), ("3D 64^3 ball", lambda: ball(64))]
    if args.large:
        inputs.append(("3D 512^3 ball r=0.45n", lambda: ball(512)))
    available = peers(args.threads)
    print("peers available:", ", ".join(available) or "none",
          "| missing:", ", ".join(sorted({"scipy", "opencv", "itk", "edt"} - set(available))) or "none")
    print(f"zdg threads={args.threads}, median of {args.repeats}; ratio = peer time / zdg time")
    with tempfile.TemporaryDirectory() as tmp:
        for name, make in inputs:
            img = make()
            row = [name]
            for metric in ("l2", "l3"):
                t, dt = run_zdg(args.zdg, img, args.threads, args.repeats, metric, tmp)
                row.append(f"zdg {metric} {t:.3f}s ({1e9 * t / img.size:.2f} ns/voxel)")
                if metric == "l2":
                    t_l2, exact = t, dt.astype(np.int64)
            for peer, fn in available.items():
                if "512^3" in name and peer == "scipy":
                    continue
                t, d = median_time(lambda: fn(img), 1 if img.size > 2e7 else args.repeats)
                if d is None:
                    continue
                d64 = np.asarray(d, dtype=np.float64)
                d2 = d64 if peer in SQUARED else d64 * d64
                agree = np.mean(np.rint(d2).astype(np.int64) == exact)
                row.append(f"{peer} {t:.3f}s ratio {t / t_l2:.2f} (exact agreement {100 * agree:.2f}%)")
            print(" | ".join(row))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
