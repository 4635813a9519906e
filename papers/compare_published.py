#!/usr/bin/python3
"""Compares a zdg run (results.csv of `zdg converge` / `zdg paper`) with the published error
bands of a paper (papers/NAME/published.csv: figure, shape, estimator, i, h, lo, hi).

For every published curve and grid step h = exp(-i/10) that the run has, the l_inf errors of
the run's translations are summarized by their median (and min, max); the level is `inside`
when lo <= median <= hi, and its ratio is median / ((lo + hi) / 2). A run's shape matches a
published one when they are equal once a leading `unprojected:` is removed.

    papers/compare_published.py OUT_DIR papers/cviu2014-ii3d/published.csv [--json]
                                [--tolerance 0.1]

Prints one line per curve: levels compared, inside the band, within the tolerance (relative
to the band's edges), the median ratio and the extreme ratios; --json prints the per-level
detail too. Exit status 0 (the comparison is a report, not a check).
"""
import csv
import json
import math
import statistics
import sys


def level(h):
    return round(-10 * math.log(h))


def base_shape(shape):
    return shape[len("unprojected:"):] if shape.startswith("unprojected:") else shape


def compare(results_csv, published_csv, tolerance=0.1):
    runs = {}
    with open(results_csv, newline="") as f:
        for r in csv.DictReader(f):
            h = float(r["h"])
            if abs(-10 * math.log(h) - level(h)) > 1e-6:
                continue  # not a step exp(-i/10)
            key = (base_shape(r["shape"]), r["estimator"], level(h))
            runs.setdefault(key, []).append(float(r["linf"]))
    curves = {}
    with open(published_csv, newline="") as f:
        for p in csv.DictReader(f):
            key = (p["shape"], p["estimator"], int(p["i"]))
            if key not in runs:
                continue
            e = runs[key]
            lo, hi = float(p["lo"]), float(p["hi"])
            med = statistics.median(e)
            c = curves.setdefault((p["figure"], p["shape"], p["estimator"]), [])
            c.append({
                "i": int(p["i"]), "h": math.exp(-int(p["i"]) / 10), "lo": lo, "hi": hi,
                "median": med, "min": min(e), "max": max(e), "runs": len(e),
                "inside": lo <= med <= hi,
                "near": lo * (1 - tolerance) <= med <= hi * (1 + tolerance),
                "ratio": med / (0.5 * (lo + hi)),
            })
    return curves


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    tolerance = 0.1
    if "--tolerance" in sys.argv:
        tolerance = float(sys.argv[sys.argv.index("--tolerance") + 1])
        args = [a for a in args if a != sys.argv[sys.argv.index("--tolerance") + 1]]
    if len(args) != 2:
        sys.exit(__doc__)
    curves = compare(args[0] + "/results.csv", args[1], tolerance)
    if "--json" in sys.argv:
        print(json.dumps([{"figure": k[0], "shape": k[1], "estimator": k[2], "levels": v}
                          for k, v in curves.items()], indent=1))
        return
    print(f"{'figure':22} {'estimator':13} {'levels':>6} {'inside':>6} "
          f"{'+-' + str(round(100 * tolerance)) + '%':>6} {'median ratio':>12} {'min..max ratio':>16}")
    for (fig, shape, est), v in curves.items():
        ratios = [x["ratio"] for x in v]
        print(f"{fig:22} {est:13} {len(v):6d} {sum(x['inside'] for x in v):6d} "
              f"{sum(x['near'] for x in v):6d} {statistics.median(ratios):12.3f} "
              f"{min(ratios):7.3f}..{max(ratios):<7.3f}")


if __name__ == "__main__":
    main()
