#!/usr/bin/python3
"""Draws DIR/convergence.png and DIR/convergence.svg from DIR/results.csv and DIR/summary.json.

One estimator: one panel, log-log error (l_inf, the worst case over translations) against h,
one colour per shape with the band of the translations (min to max of their l_inf), the
fitted slope in the legend, and reference slope triangles for the proven rates.
Several estimators (a comparison): one column per shape; on top the l_inf errors of all the
estimators against h, one colour per estimator (slope and verdict in the legend, the proven
rates as triangles); below, the computation time per run (mean over the translations)
against h, same colours.

Usage: /usr/bin/python3 papers/plot_convergence.py DIR
       /usr/bin/python3 papers/plot_convergence.py --csv RESULTS --summary SUMMARY \
           --png PNG --svg SVG
The second form (used by zdg converge) reads and writes the given paths, whatever their names:
zdg hands over its staging files and moves them in place only when everything succeeded.
"""
import csv
import json
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, summary_path, outputs):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    with open(summary_path) as f:
        summary = json.load(f)
    fits = {(x["shape"], x["estimator"]): x for x in summary["fits"] if x["norm"] == "linf"}
    estimators = []
    for r in rows:
        if r["estimator"] not in estimators:
            estimators.append(r["estimator"])
    if len(estimators) > 1:
        fig = draw_comparison(rows, summary, fits, estimators)
        save(fig, csv_path, outputs, summary)
        return
    fig, axes = plt.subplots(1, len(estimators), figsize=(6 * len(estimators), 4.8), squeeze=False)
    for ax, est in zip(axes[0], estimators):
        by_shape = defaultdict(lambda: defaultdict(list))
        for r in rows:
            if r["estimator"] == est:
                by_shape[r["shape"]][float(r["h"])].append(float(r["linf"]))
        all_h = []
        for shape, per_h in by_shape.items():
            hs = sorted(per_h)
            worst = [max(per_h[h]) for h in hs]
            low = [min(per_h[h]) for h in hs]
            fit = fits.get((shape, est))
            label = shape
            if fit and fit.get("slope") is not None:
                label += " (slope %.2f" % fit["slope"]
                if fit.get("expected") is not None:
                    label += ", theory >= %.2f: %s" % (
                        fit["expected"], "pass" if fit.get("pass") else "FAIL")
                label += ")"
            pos = [(h, w, l) for h, w, l in zip(hs, worst, low) if w > 0]
            if not pos:
                continue
            line, = ax.loglog([p[0] for p in pos], [p[1] for p in pos], "o-", ms=3, label=label)
            if any(l != w for _, w, l in pos):
                ax.fill_between([p[0] for p in pos], [max(p[2], 1e-300) for p in pos],
                                [p[1] for p in pos], color=line.get_color(), alpha=0.2)
            all_h += hs
        # Reference slope triangles for the proven rates of this estimator.
        drawn = set()
        for (shape, e), fit in fits.items():
            if e != est or fit.get("expected") is None or fit["expected"] in drawn:
                continue
            drawn.add(fit["expected"])
            s = fit["expected"]
            per_h = by_shape.get(shape, {})
            hs = sorted(per_h)
            if len(hs) < 2:
                continue
            h0, h1 = hs[0], hs[0] * math.exp(0.35 * math.log(hs[-1] / hs[0]))
            y0 = max(per_h[h0]) * 0.5
            if y0 <= 0:
                continue
            y1 = y0 * (h1 / h0) ** s
            ax.loglog([h0, h1, h1, h0], [y0, y0, y1, y0], "k-", lw=0.8)
            ax.text(h1, math.sqrt(y0 * y1), " %.2f" % s, fontsize=8, va="center")
        ax.set_xlabel("h")
        ax.set_ylabel("l_inf error")
        ax.set_title(est)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=7)
    save(fig, csv_path, outputs, summary)


def slope_label(name, fit):
    label = name
    if fit and fit.get("slope") is not None:
        label += " (slope %.2f" % fit["slope"]
        if fit.get("expected") is not None:
            label += ", theory >= %.2f: %s" % (fit["expected"], "pass" if fit.get("pass") else "FAIL")
        label += ")"
    return label


def draw_comparison(rows, summary, fits, estimators):
    shapes = []
    for r in rows:
        if r["shape"] not in shapes:
            shapes.append(r["shape"])
    fig, axes = plt.subplots(2, len(shapes), figsize=(7 * len(shapes), 8.4), squeeze=False,
                             gridspec_kw={"height_ratios": [3, 2]})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for col, shape in enumerate(shapes):
        err_ax, time_ax = axes[0][col], axes[1][col]
        drawn = set()
        for i, est in enumerate(estimators):
            colour = colours[i % len(colours)]
            errs, secs = defaultdict(list), defaultdict(list)
            for r in rows:
                if r["shape"] == shape and r["estimator"] == est:
                    errs[float(r["h"])].append(float(r["linf"]))
                    secs[float(r["h"])].append(float(r.get("seconds") or 0.0))
            hs = sorted(errs)
            pos = [(h, max(errs[h])) for h in hs if max(errs[h]) > 0]
            fit = fits.get((shape, est))
            if pos:
                err_ax.loglog([p[0] for p in pos], [p[1] for p in pos], "o-", ms=3, color=colour,
                              label=slope_label(est, fit))
            if fit and fit.get("expected") is not None and len(pos) >= 2 and \
                    (est, fit["expected"]) not in drawn:
                drawn.add((est, fit["expected"]))
                s = fit["expected"]
                h0, h1 = pos[0][0], pos[0][0] * math.exp(0.35 * math.log(pos[-1][0] / pos[0][0]))
                y0 = pos[0][1] * 0.5
                y1 = y0 * (h1 / h0) ** s
                err_ax.loglog([h0, h1, h1, h0], [y0, y0, y1, y0], "-", color=colour, lw=0.8)
                err_ax.text(h1, math.sqrt(y0 * y1), " %.2f" % s, fontsize=8, va="center",
                            color=colour)
            tpos = [(h, sum(secs[h]) / len(secs[h])) for h in hs if secs[h] and sum(secs[h]) > 0]
            if tpos:
                time_ax.loglog([p[0] for p in tpos], [p[1] for p in tpos], "s-", ms=3,
                               color=colour, label=est)
        err_ax.set_title(shape)
        err_ax.set_xlabel("h")
        err_ax.set_ylabel("l_inf error (each estimator's quantity)")
        err_ax.grid(True, which="both", lw=0.3)
        err_ax.legend(fontsize=7)
        families = defaultdict(int)
        for est in estimators:
            for prefix in ("ii-", "jet-"):
                if est.startswith(prefix):
                    families[prefix] += 1
        if any(n > 1 for n in families.values()):
            time_ax.set_title("estimators sharing one computation (%s*) charge it to the first "
                              "of them run" % "*, ".join(p for p, n in families.items() if n > 1),
                              fontsize=8)
        time_ax.set_xlabel("h")
        time_ax.set_ylabel("seconds per run")
        time_ax.grid(True, which="both", lw=0.3)
        time_ax.legend(fontsize=7)
    return fig


def save(fig, csv_path, outputs, summary=None):
    title = (summary or {}).get("config", {}).get("title") or ""
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    for ext, path in outputs:
        if path is None:
            # DIR form: a temporary file beside the target, then a rename.
            tmp = os.path.join(os.path.dirname(csv_path), "convergence.tmp." + ext)
            fig.savefig(tmp, dpi=120, format=ext)
            os.replace(tmp, os.path.join(os.path.dirname(csv_path), "convergence." + ext))
        else:
            fig.savefig(path, dpi=120, format=ext)


if __name__ == "__main__":
    import argparse

    if len(sys.argv) == 2 and not sys.argv[1].startswith("-"):
        d = sys.argv[1]
        main(os.path.join(d, "results.csv"), os.path.join(d, "summary.json"),
             [("png", None), ("svg", None)])
    else:
        ap = argparse.ArgumentParser(description="Draw the convergence plot of a zdg run.")
        ap.add_argument("--csv", required=True)
        ap.add_argument("--summary", required=True)
        ap.add_argument("--png", required=True)
        ap.add_argument("--svg", required=True)
        a = ap.parse_args()
        main(a.csv, a.summary, [("png", a.png), ("svg", a.svg)])
