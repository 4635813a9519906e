#!/usr/bin/python3
"""Draws DIR/convergence.png, DIR/convergence.svg and DIR/convergence.html from DIR/results.csv
and DIR/summary.json.

One estimator: one panel, log-log error (l_inf, the worst case over translations) against h,
one colour per shape with the band of the translations (min to max of their l_inf), the
fitted slope in the legend, and reference slope triangles for the proven rates.
Several estimators (a comparison): one column per shape; on top the l_inf errors of all the
estimators against h, one colour per estimator (slope and verdict in the legend, the proven
rates as triangles); below, the computation time per run (mean over the translations)
against h, same colours.

Published curves: with a published.csv (papers/NAME/published.csv: figure, shape, estimator,
i, h, lo, hi), each published curve that matches the run (papers/compare_published.py's
matching: the shape without a leading `unprojected:`, the estimator, the levels
h = exp(-i/10) that the run has) is drawn as a hatched band lo..hi (a dashed line where
lo = hi) in the colour of its run curve, labelled "published: FIGURE", in the PNG, the SVG
and the page.

The page (convergence.html, papers/convergence_page.html filled with the run's data) is one
self-contained file, no network and no library: the log-log errors against h of every series
(shape x estimator x norm of results.csv; per h, l_inf is the largest over the translations,
as in the PNG and the fit, l_2 and mean their mean, as in the fit, with the band of the
translations' min..max and a dot per translation), a tooltip on every point (h, error,
translation), a checkbox per shape, estimator and norm, the slope triangles of the proven
rates, the verdicts of summary.json's fits, the published bands and a legend.

A samples sweep (results.csv with a `samples` column, `zdg converge --samples`) is drawn the same
way against the number of points N in place of h (the x axis says N; the proven rates are
exponents of N, checked as slope <= rate).

Usage: /usr/bin/python3 papers/plot_convergence.py DIR [--published CSV]
       /usr/bin/python3 papers/plot_convergence.py --csv RESULTS --summary SUMMARY \
           --png PNG --svg SVG [--html HTML] [--published CSV]
The first form writes the three files in DIR; its published.csv is CSV, or else the one beside
the config file that summary.json names (config.config_file), when there is one. The second
form (used by zdg converge) reads and writes the given paths, whatever their names, and draws
published curves only from --published: zdg hands over its staging files and moves them in
place only when everything succeeded.
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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_published  # noqa: E402

PAGE_TEMPLATE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "convergence_page.html")
NORMS = ("linf", "l2", "mean")  # the error columns of results.csv
VARIABLE = "h"  # the x axis: "N" for a samples sweep (set by main)


def main(csv_path, summary_path, outputs, html_path=None, published_path=None):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    global VARIABLE
    VARIABLE = "N" if rows and rows[0].get("samples") else "h"
    if VARIABLE == "N":  # a samples sweep: the levels are the counts N
        for r in rows:
            r["h"] = r["samples"]
    with open(summary_path) as f:
        summary = json.load(f)
    published = published_curves(csv_path, published_path, rows) if published_path else []
    if html_path is not None:
        write_page(html_path, rows, summary, published)
    fits = {(x["shape"], x["estimator"]): x for x in summary["fits"] if x["norm"] == "linf"}
    estimators = []
    for r in rows:
        if r["estimator"] not in estimators:
            estimators.append(r["estimator"])
    if len(estimators) > 1:
        fig = draw_comparison(rows, summary, fits, estimators, published)
        save(fig, csv_path, outputs, summary)
        return
    fig, axes = plt.subplots(1, len(estimators), figsize=(6 * len(estimators), 4.8), squeeze=False)
    for ax, est in zip(axes[0], estimators):
        by_shape = defaultdict(lambda: defaultdict(list))
        for r in rows:
            if r["estimator"] == est:
                by_shape[r["shape"]][float(r["h"])].append(float(r["linf"]))
        all_h = []
        colours = {}
        for shape, per_h in by_shape.items():
            hs = sorted(per_h)
            worst = [max(per_h[h]) for h in hs]
            low = [min(per_h[h]) for h in hs]
            fit = fits.get((shape, est))
            label = shape
            if fit and fit.get("slope") is not None:
                label += " (slope %.2f" % fit["slope"]
                if fit.get("expected") is not None:
                    label += ", theory %s %.2f: %s" % (
                        ">=" if VARIABLE == "h" else "<=", fit["expected"],
                        "pass" if fit.get("pass") else "FAIL")
                label += ")"
            pos = [(h, w, l) for h, w, l in zip(hs, worst, low) if w > 0]
            if not pos:
                continue
            line, = ax.loglog([p[0] for p in pos], [p[1] for p in pos], "o-", ms=3, label=label)
            colours[shape] = line.get_color()
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
        for curve in published:
            if curve["estimator"] == est:
                colour = next((colours[s] for s in curve["shapes"] if s in colours), "0.4")
                draw_published(ax, curve, colour)
        ax.set_xlabel(VARIABLE)
        ax.set_ylabel("l_inf error")
        ax.set_title(est)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=7)
    save(fig, csv_path, outputs, summary)


def published_curves(csv_path, published_path, rows):
    """The published curves that match the run (compare_published.compare), each with its
    levels sorted by h and the run's shapes it stands for."""
    shapes = []
    for r in rows:
        if r["shape"] not in shapes:
            shapes.append(r["shape"])
    out = []
    for (figure, shape, est), levels in compare_published.compare(csv_path, published_path).items():
        levels = sorted(levels, key=lambda x: x["h"])
        out.append({"figure": figure, "shape": shape, "estimator": est,
                    "shapes": [s for s in shapes if compare_published.base_shape(s) == shape],
                    "h": [x["h"] for x in levels], "lo": [x["lo"] for x in levels],
                    "hi": [x["hi"] for x in levels]})
    return out


def draw_published(ax, curve, colour):
    """A published curve on log-log axes: the hatched band lo..hi, or a dashed line where the
    band has no width."""
    pts = [(h, lo, hi) for h, lo, hi in zip(curve["h"], curve["lo"], curve["hi"]) if lo > 0]
    if not pts:
        return
    ax.set_xscale("log")
    ax.set_yscale("log")
    label = "published: " + curve["figure"]
    hs, lo, hi = [p[0] for p in pts], [p[1] for p in pts], [p[2] for p in pts]
    if lo == hi:
        ax.plot(hs, lo, "--", color=colour, lw=1, label=label)
    else:
        ax.fill_between(hs, lo, hi, facecolor="none", edgecolor=colour, hatch="///", lw=0.6,
                        label=label)


def finite(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def page_data(rows, summary, published):
    """The page's data: one series per (shape, estimator, norm) of results.csv, in the order of
    the file; per h the aggregate the fit uses (l_inf: the largest over the translations, with
    the translation that gave it; l_2 and mean: their mean) and every translation's value."""
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    pairs, shapes, estimators = [], [], []
    for r in rows:
        if (r["shape"], r["estimator"]) not in pairs:
            pairs.append((r["shape"], r["estimator"]))
        if r["shape"] not in shapes:
            shapes.append(r["shape"])
        if r["estimator"] not in estimators:
            estimators.append(r["estimator"])
    fits = {(f["shape"], f["estimator"], f["norm"]): f for f in summary.get("fits", [])}
    series = []
    for index, (shape, est) in enumerate(pairs):
        colour = colours[index % len(colours)]
        for norm in NORMS:
            per_h = defaultdict(list)
            for r in rows:
                if r["shape"] == shape and r["estimator"] == est:
                    v = finite(r[norm])
                    if v is not None:
                        per_h[float(r["h"])].append((int(r["translation"]), v))
            points, runs = [], []
            for h in sorted(per_h, reverse=True):
                values = per_h[h]
                if norm == "linf":
                    translation, error = max(values, key=lambda x: x[1])
                else:
                    translation, error = None, sum(v for _, v in values) / len(values)
                points.append({"h": h, "error": error, "translation": translation,
                               "runs": len(values), "min": min(v for _, v in values),
                               "max": max(v for _, v in values)})
                runs += [{"h": h, "error": v, "translation": t} for t, v in values]
            fit = fits.get((shape, est, norm))
            series.append({"shape": shape, "estimator": est, "norm": norm, "colour": colour,
                           "points": points, "runs": runs,
                           "fit": None if fit is None else {
                               k: fit.get(k) for k in ("slope", "stderr", "levels", "h_min",
                                                       "h_max", "samples_min", "samples_max",
                                                       "expected", "pass", "reason")}})
    pages_published = []
    for curve in published:
        colour = next((s["colour"] for s in series if s["shape"] in curve["shapes"]
                       and s["estimator"] == curve["estimator"]), "#666666")
        pages_published.append({
            "figure": curve["figure"], "shape": curve["shape"], "shapes": curve["shapes"],
            "estimator": curve["estimator"], "colour": colour,
            "points": [{"h": h, "lo": lo, "hi": hi}
                       for h, lo, hi in zip(curve["h"], curve["lo"], curve["hi"])]})
    config = summary.get("config", {})
    return {"title": config.get("title") or "", "variable": VARIABLE,
            "h": config.get("h") if VARIABLE == "h" else config.get("samples"),
            "translations": config.get("translations"), "all_pass": summary.get("all_pass"),
            "commit": summary.get("provenance", {}).get("commit"),
            "shapes": shapes, "estimators": estimators, "norms": list(NORMS),
            "series": series, "published": pages_published}


def write_page(path, rows, summary, published):
    """convergence.html: the template with the data inlined (as JSON that cannot close the
    script element)."""
    with open(PAGE_TEMPLATE) as f:
        template = f.read()
    marker = "/*ZDG_DATA*/null"
    if template.count(marker) != 1:
        raise RuntimeError(PAGE_TEMPLATE + " has no single " + marker)
    data = json.dumps(page_data(rows, summary, published), allow_nan=False)
    data = data.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")
    with open(path, "w") as f:
        f.write(template.replace(marker, data))


def slope_label(name, fit):
    label = name
    if fit and fit.get("slope") is not None:
        label += " (slope %.2f" % fit["slope"]
        if fit.get("expected") is not None:
            label += ", theory %s %.2f: %s" % (">=" if VARIABLE == "h" else "<=", fit["expected"],
                                               "pass" if fit.get("pass") else "FAIL")
        label += ")"
    return label


def draw_comparison(rows, summary, fits, estimators, published):
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
            for curve in published:
                if curve["estimator"] == est and shape in curve["shapes"]:
                    draw_published(err_ax, curve, colour)
        err_ax.set_title(shape)
        err_ax.set_xlabel(VARIABLE)
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
        time_ax.set_xlabel(VARIABLE)
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


def published_beside_config(summary_path):
    """The published.csv in the directory of the config file that summary.json names, if any."""
    with open(summary_path) as f:
        config_file = json.load(f).get("config", {}).get("config_file") or ""
    if not config_file:
        return None
    candidate = os.path.join(os.path.dirname(config_file), "published.csv")
    return candidate if os.path.isfile(candidate) else None


if __name__ == "__main__":
    import argparse

    if len(sys.argv) >= 2 and not sys.argv[1].startswith("-"):
        ap = argparse.ArgumentParser(description="Draw the convergence plot of a zdg run in DIR.")
        ap.add_argument("dir")
        ap.add_argument("--published")
        a = ap.parse_args()
        d = a.dir
        summary_path = os.path.join(d, "summary.json")
        published = a.published or published_beside_config(summary_path)
        html_tmp = os.path.join(d, "convergence.tmp.html")
        try:
            main(os.path.join(d, "results.csv"), summary_path, [("png", None), ("svg", None)],
                 html_tmp, published)
        except BaseException:
            if os.path.exists(html_tmp):
                os.remove(html_tmp)
            raise
        os.replace(html_tmp, os.path.join(d, "convergence.html"))
    else:
        ap = argparse.ArgumentParser(description="Draw the convergence plot of a zdg run.")
        ap.add_argument("--csv", required=True)
        ap.add_argument("--summary", required=True)
        ap.add_argument("--png", required=True)
        ap.add_argument("--svg", required=True)
        ap.add_argument("--html", help="also write the interactive page here")
        ap.add_argument("--published", help="published.csv of the paper: its matching curves")
        a = ap.parse_args()
        main(a.csv, a.summary, [("png", a.png), ("svg", a.svg)], a.html, a.published)
