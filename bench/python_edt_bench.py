#!/usr/bin/python3
"""The exact distance transform from Python: zdg.distance_transform (zero-copy) against the
C++ library called directly (build/bin/transform_bench, the same input) and scipy.ndimage.

Input: the ball of radius 0.45 n in n^3 of bench/transform_bench.cpp (n = 256; --n 512 for
the large one). Prints median seconds over --repeat calls, the ratio Python / C++ (the cost of
the binding) and scipy / zdg, and the peak resident memory of this process against
input + output (zero-copy: no third buffer).

  PYTHONPATH=build/python /usr/bin/python3 bench/python_edt_bench.py --threads 2 \\
      --cxx build/bin/transform_bench
"""
import argparse
import json
import statistics
import subprocess
import time
import tracemalloc

import numpy as np

import zdg


def ball(n):
    c, r = n // 2, 45 * n // 100
    z, y, x = np.ogrid[:n, :n, :n]
    return ((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2 < r * r).astype(np.uint8)


def current_rss():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    return 0


def peak_rss_reset():
    """Resets the kernel's peak resident size of this process (Linux >= 4.0)."""
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
    except OSError:
        pass
    return peak_rss()


def peak_rss():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) * 1024
    return 0


def median_seconds(f, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--cxx", help="path of build/bin/transform_bench (C++ reference time)")
    ap.add_argument("--no-scipy", action="store_true")
    a = ap.parse_args()

    image = ball(a.n)
    # Memory of one call: numpy reports its allocations to tracemalloc (the output array);
    # the process's resident size is read from /proc before and at the peak of the call.
    rss_before = current_rss()
    peak = peak_rss_reset()
    tracemalloc.start()
    out = zdg.distance_transform(image, threads=a.threads)
    _, traced = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    peak = peak_rss()
    print(f"input {image.nbytes / 2**20:.0f} MiB uint8, output {out.nbytes / 2**20:.0f} MiB "
          f"{out.dtype}; allocated by the call {traced / 2**20:.1f} MiB; resident size grew by "
          f"{(peak - rss_before) / 2**20:.1f} MiB at the peak of the call")
    del out
    t_py = median_seconds(lambda: zdg.distance_transform(image, threads=a.threads), a.repeat)
    print(f"zdg.distance_transform {a.n}^3 l2, {a.threads} threads: {t_py:.3f} s (median of "
          f"{a.repeat})")
    if a.cxx:
        name = f"Dt3dNew/{a.n}/2/{a.threads}"  # allocating its output, like the binding
        res = subprocess.run([a.cxx, f"--benchmark_filter=^{name}/", "--benchmark_format=json",
                              f"--benchmark_repetitions={a.repeat}"],
                             check=True, capture_output=True, text=True)
        runs = [b for b in json.loads(res.stdout)["benchmarks"]
                if b.get("run_type") == "iteration"]
        t_cxx = statistics.median(b["real_time"] / 1e3 if b["time_unit"] == "ms" else b["real_time"]
                                  for b in runs)
        print(f"C++ transform_bench {name}: {t_cxx:.3f} s (median of {len(runs)}); "
              f"Python / C++ = {t_py / t_cxx:.3f}")
    if not a.no_scipy:
        from scipy import ndimage
        ref = None

        def run_scipy():
            nonlocal ref
            ref = ndimage.distance_transform_edt(image)

        t_sp = median_seconds(run_scipy, max(1, min(a.repeat, 3)))
        ours = zdg.distance_transform(image, threads=a.threads)
        assert np.array_equal(np.rint(ref * ref).astype(np.int64), ours)
        print(f"scipy.ndimage.distance_transform_edt (1 thread, float64): {t_sp:.3f} s; "
              f"scipy / zdg = {t_sp / t_py:.1f} (results equal after squaring and rounding)")


if __name__ == "__main__":
    main()
