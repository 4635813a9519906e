#!/usr/bin/python3
"""The tables of papers/reconstruction/README.md from a run of `zdg paper reconstruction`:

  /usr/bin/python3 papers/reconstruction/table.py DIR

DIR holds the run's results.csv and summary.json. Prints (markdown):
  1. topology: per method and shape, the smallest N from which the Betti numbers of the
     reconstruction are the shape's for every sampling at that N and every larger N of the
     sweep ("never" when the largest N fails), with the failed samplings over all samplings;
  2. rates: the fitted slopes against log N of the Hausdorff distance (l_inf, with the proven
     rate and the verdict where theory gives one) and of the mean normal angle, and the
     Hausdorff l_inf at the largest N.
"""
import csv
import json
import os
import sys
from collections import defaultdict


def main(d):
    with open(os.path.join(d, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(d, "summary.json")) as f:
        fits = json.load(f)["fits"]
    shapes, methods = [], []
    betti = defaultdict(lambda: defaultdict(list))  # (method, shape) -> N -> errors
    last = {}
    for r in rows:
        kind, method = r["estimator"].split(":method=")
        if r["shape"] not in shapes:
            shapes.append(r["shape"])
        if method not in methods:
            methods.append(method)
        n = int(r["samples"])
        if kind == "recon-betti":
            betti[(method, r["shape"])][n].append(float(r["linf"]))
        if kind == "recon-hausdorff":
            key = (method, r["shape"])
            if key not in last or n > last[key][0]:
                last[key] = (n, float(r["linf"]))
            elif n == last[key][0]:
                last[key] = (n, max(last[key][1], float(r["linf"])))
    print("Topology: the smallest N from which every sampling gets the shape's Betti numbers "
          "(failed samplings / all)\n")
    print("| method | " + " | ".join(shapes) + " |")
    print("|---" * (len(shapes) + 1) + "|")
    for m in methods:
        cells = []
        for s in shapes:
            per_n = betti.get((m, s))
            if not per_n:
                cells.append("-")
                continue
            ns = sorted(per_n)
            first = None
            for n in reversed(ns):
                if any(e != 0 for e in per_n[n]):
                    break
                first = n
            failed = sum(1 for n in ns for e in per_n[n] if e != 0)
            total = sum(len(per_n[n]) for n in ns)
            cells.append("%s (%d/%d)" % ("never" if first is None else str(first), failed, total))
        print("| %s | %s |" % (m, " | ".join(cells)))
    by = {(f["estimator"], f["shape"], f["norm"]): f for f in fits}
    print("\nRates: slopes of log(error) against log(N)\n")
    print("| method | shape | Hausdorff l_inf slope | proven | verdict | Hausdorff l_inf at "
          "the largest N | normal angle mean slope |")
    print("|---|---|---|---|---|---|---|")
    for m in methods:
        for s in shapes:
            h = by.get(("recon-hausdorff:method=" + m, s, "linf"))
            nm = by.get(("recon-normal:method=" + m, s, "mean"))
            if h is None:
                continue

            def slope(f):
                if f is None or f.get("slope") is None:
                    return "-"
                return "%.2f +- %.2f" % (f["slope"], f.get("stderr") or 0)
            proven = "-" if h.get("expected") is None else "%.2f" % h["expected"]
            verdict = "-" if h.get("pass") is None else ("pass" if h["pass"] else "FAIL")
            n, e = last.get((m, s), (0, float("nan")))
            print("| %s | %s | %s | %s | %s | %.3g (N = %d) | %s |" % (
                m, s, slope(h), proven, verdict, e, n, slope(nm)))


if __name__ == "__main__":
    main(sys.argv[1])
