#!/usr/bin/python3
"""The Laplacian comparison of Wardetzky, Mathur, Kalberer, Grinspun ("Discrete Laplace
operators: no free lunch", SGP 2007) measured on digital surfaces: the property table
(symmetry, locality, linear precision, positive weights) of `zdg laplacians` and the
convergence of Delta u of `zdg converge` (the lb-* estimators), merged into one table.

    /usr/bin/python3 papers/laplacian-comparison/run.py -o DIR [--quick] [--zdg build/bin/zdg]
    zdg paper laplacian-comparison -o DIR [--quick]        (the same, with this zdg)

Outputs in DIR: results.csv, summary.json, convergence.png / .svg / .html (zdg converge on
convergence.toml, or convergence-quick.toml with --quick: every operator on the unit sphere,
u = x, x^2 - y^2, exp(z)), properties.json (zdg laplacians --json: the unit sphere at
h = 0.1, or 0.2 with --quick; the faces of a rotated cube of half-side 20, or 14, at h = 1), and
table.md / table.json (one row per operator: the measured properties and the fitted slopes of
the l_inf and mean errors per u). The exit status is zdg converge's (1: a theory check failed).
"""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# What Wardetzky et al. 2007 list for each operator on general meshes (their Table 1, as we
# read it, for the four properties; "-" where the operator is not in their table), beside what
# zdg measures. (op, label, claimed: sym, loc, lin, pos)
OPERATORS = [
    ("cotan", "cotangent, primal quads split", ("yes", "yes", "yes", "no")),
    ("cotan-mc", "cotangent, marching cubes", ("yes", "yes", "yes", "no")),
    ("meanvalue", "mean value (Floater 2003)", ("no", "yes", "yes", "yes")),
    ("idt", "intrinsic Delaunay (Bobenko, Springborn 2007)", ("yes", "no", "yes", "yes")),
    ("polygonal", "polygonal (de Goes et al. 2020), lambda = 1", ("-", "-", "-", "-")),
    ("heat", "heat kernel (Belkin et al. 2008; Caissard et al. 2019)", ("yes", "no", "no", "yes")),
    ("combinatorial", "combinatorial (graph)", ("yes", "yes", "no", "yes")),
]
FUNCTIONS = ["x", "x^2-y^2", "exp(z)"]


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def slopes(summary, estimator, norm):
    """The fitted slope (+- its standard error) of estimator:u=F for each F, on sphere1."""
    out = {}
    for fit in summary["fits"]:
        name = fit["estimator"]
        if fit["norm"] != norm or not name.startswith(estimator + ":u="):
            continue
        out[name[len(estimator) + 3:]] = (fit["slope"], fit["stderr"])
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--zdg", default=os.path.join(ROOT, "build", "bin", "zdg"))
    a = ap.parse_args()
    os.makedirs(a.output, exist_ok=True)
    config = os.path.join(HERE, "convergence-quick.toml" if a.quick else "convergence.toml")
    h, cube = ("0.2", "14") if a.quick else ("0.1", "20")

    # The property table first (a bad build fails here, before the sweep).
    p = subprocess.run([a.zdg, "laplacians", "--json", "--shape", "sphere1", "--h", h, "--cube",
                        cube], capture_output=True, text=True)
    if p.returncode != 0:
        sys.stderr.write(p.stderr)
        return 2
    props = json.loads(p.stdout)
    write_atomic(os.path.join(a.output, "properties.json"), json.dumps(props, indent=2) + "\n")

    # The convergence sweep (the caller checked the folder: zdg paper refuses a summary.json
    # there without --force).
    c = subprocess.run([a.zdg, "converge", config, "-o", a.output, "--force", "--quiet"],
                       stdout=subprocess.DEVNULL)
    if c.returncode not in (0, 1):
        return c.returncode
    with open(os.path.join(a.output, "summary.json")) as f:
        summary = json.load(f)

    by_op = {r["operator"]: r for r in props["operators"]}
    rows = []
    for op, label, claimed in OPERATORS:
        r = by_op[op]
        linf = slopes(summary, r["estimator"], "linf")
        mean = slopes(summary, r["estimator"], "mean")
        rows.append({
            "operator": op,
            "label": label,
            "estimator": r["estimator"],
            "claimed": dict(zip(["symmetry", "locality", "linear_precision", "positive_weights"],
                                claimed)),
            "asymmetry": r["asymmetry"],
            "mean_row_entries": r["mean_row_entries"],
            "max_row_entries": r["max_row_entries"],
            "support_radius_h": r["support_radius"],
            "linear_defect": r["linear_defect"],
            "negative_fraction": r["negative_fraction"],
            "min_weight": r["min_weight"],
            "constants": r["constants"],
            "slope_linf": {u: linf[u][0] for u in linf},
            "slope_mean": {u: mean[u][0] for u in mean},
        })
    table = {
        "properties_on": {"shape": props["shape"], "h": props["h"], "cube": props["cube"]},
        "convergence_on": {"config": os.path.relpath(config, ROOT),
                           "h": summary["config"].get("h") if isinstance(summary.get("config"), dict) else None},
        "rows": rows,
    }
    write_atomic(os.path.join(a.output, "table.json"), json.dumps(table, indent=2) + "\n")

    def slope_text(d):
        return " / ".join("%.2f" % d[u] if u in d else "-" for u in FUNCTIONS)

    md = ["# Discrete Laplacians on digital surfaces: the properties of Wardetzky et al. 2007, measured",
          "",
          "Properties on %s at h = %s; linear precision on the faces of a rotated digital cube of "
          "half-side %s at h = 1 (max abs(L u), |grad u| = 1); convergence: slopes of the l_inf "
          "and mean errors of L u against Delta_S u on %s (u = %s), from %s. Claimed: Wardetzky "
          "et al.'s table for general meshes (sym, loc, lin, pos)."
          % (props["shape"], props["h"], props["cube"]["half_side"], props["shape"],
             ", ".join(FUNCTIONS), os.path.relpath(config, ROOT)),
          "",
          "| operator | claimed sym/loc/lin/pos | asymmetry of W L | entries per row (mean, max) "
          "| support / h | linear u: max abs(L u) | negative weights | l_inf slope (u = x / x^2-y^2 "
          "/ exp(z)) | mean-error slope |",
          "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        md.append("| %s | %s | %.1e | %.1f, %d | %.3g | %.3g | %.3g%% | %s | %s |" % (
            r["label"], "/".join(r["claimed"].values()), r["asymmetry"], r["mean_row_entries"],
            r["max_row_entries"], r["support_radius_h"], r["linear_defect"],
            100 * r["negative_fraction"], slope_text(r["slope_linf"]),
            slope_text(r["slope_mean"])))
    md.append("")
    text = "\n".join(md)
    write_atomic(os.path.join(a.output, "table.md"), text)
    print(text)
    print("table:   %s\nfigure:  %s" % (os.path.join(a.output, "table.md"),
                                       os.path.join(a.output, "convergence.png")))
    return c.returncode


if __name__ == "__main__":
    sys.exit(main())
