#!/usr/bin/python3
"""The README's main figure from Python: integral-invariant curvature on the ellipse (20, 7),
the flower and the accelerated flower (Coeurjolly, Lachaud, Levallois, CVIU 2014), l_inf
error against h with R = k h^{1/3}, fitted slopes checked against the proven 1/3.

  PYTHONPATH=build/python python3 python/examples/converge_figure.py [--quick] [-o ii2d.png]

Without --quick a small sweep (seconds); --quick is papers/cviu2014-ii2d/quick.toml (the
sweep of scripts/run-main.sh, minutes on two cores).
"""
import argparse

import zdg

ap = argparse.ArgumentParser()
ap.add_argument("--quick", action="store_true")
ap.add_argument("-o", "--output", default="ii2d.png")
ap.add_argument("--threads", type=int, default=2)
a = ap.parse_args()

r = zdg.converge(["ellipse:20,7", "flower:20,7,6", "accflower:20,5,0.60792710185402662"],
                 ["ii-curvature"], h="exp:40:85:3" if a.quick else "exp:10:40:5", k="5,5,3",
                 alpha="1/3", translations=3 if a.quick else 1, seed=2014,
                 fit_levels=8 if a.quick else 0, threads=a.threads)
for f in r["fits"]:
    if f["norm"] == "linf":
        verdict = ("no proven rate on this shape" if f["expected"] is None else
                   f"proven {f['expected']:.3f}: {'pass' if f['pass'] else 'FAIL'}")
        print(f"{f['shape']:45s} slope {f['slope']:.3f} ({verdict})")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
ax = zdg.plot(r)
ax.set_title("II curvature, l_inf error (CVIU 2014)")
ax.figure.savefig(a.output, dpi=120)
print(f"-> {a.output}")
