"""Convergence experiments from Python: the records of the C++ driver, the fits and verdicts,
and the Pick's-theorem exact case."""
import math

import pytest

import zdg


def test_ii_curvature_on_the_ellipse_converges_at_the_proven_rate():
    r = zdg.converge(["ellipse:20,7"], ["ii-curvature"], h="0.5:0.05:5", k=5, threads=2)
    assert len(r["runs"]) == 5
    assert r["threads"] == 2  # five runs on two workers (issue #34: the count used)
    hs = [x["h"] for x in r["runs"]]
    assert hs == sorted(hs, reverse=True) and math.isclose(hs[0], 0.5) and math.isclose(hs[-1], 0.05)
    assert all(x["shape"] == "ellipse:20,7" and x["estimator"] == "ii-curvature" and x["n"] > 0
               for x in r["runs"])
    linf = [f for f in r["fits"] if f["norm"] == "linf"]
    assert len(linf) == 1
    f = linf[0]
    assert math.isclose(f["expected"], 1 / 3) and f["slope"] > 1 / 3 - 0.1 and f["pass"]
    assert r["all_pass"]
    # The fit is the least-squares line of log(error) against log(h) (per level, linf).
    xs = [math.log(x["h"]) for x in r["runs"]]
    ys = [math.log(x["linf"]) for x in r["runs"]]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    assert math.isclose(f["slope"], slope, rel_tol=1e-9)


def test_translations_and_list_of_grid_steps():
    r = zdg.converge(["ellipse:20,7"], ["moments", "mlp-length"], h=[0.4, 0.2, 0.1],
                     translations=2, seed=3)
    assert len(r["runs"]) == 2 * 3 * 2
    assert {x["translation"] for x in r["runs"]} == {0, 1}


def test_plot_draws_one_curve_per_entry():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    r = zdg.converge(["ellipse:20,7"], ["moments", "mlp-length"], h=[0.4, 0.2, 0.1])
    ax = zdg.plot(r)
    assert len(ax.get_lines()) == 2


def test_bad_input():
    with pytest.raises(ValueError, match="shape"):
        zdg.converge(["no-such-shape:1"], ["moments"], h=[0.5])
    with pytest.raises(ValueError, match="h"):
        zdg.converge(["ellipse:20,7"], ["moments"], h="nonsense")
    with pytest.raises(ValueError):
        zdg.converge(["ellipse:20,7"], ["no-such-estimator"], h=[0.5])
