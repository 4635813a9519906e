"""The convergence page of `zdg converge` (convergence.html, papers/plot_convergence.py) and the
published curves of papers/NAME/published.csv in the PNG, the SVG and the page.

A small run (two 2D shapes, two estimators, three grid steps h = exp(-i/10), two translations)
from a config file, once alone and once beside a published.csv that the test writes: two of its
curves match the run (a band, and a curve with lo = hi), two do not (a level and a shape the run
lacks). Without a browser: the SVG names the published curves and draws the hatched band; the
script's DIR form finds published.csv through summary.json; a plot that cannot be drawn leaves
no page. In headless Chromium driven by Selenium (Debian: chromium, chromium-driver,
python3-selenium): the page loads with no console error, draws one curve per series of
results.csv with a positive error plus the published ones, its checkboxes hide curves, and the
tooltip of a point gives the h and the error of results.csv. Without the browser those tests
report themselves skipped with the reason, unless ZDG_REQUIRE_BROWSER=1 (CI), where that is a
failure."""
import csv
import json
import math
import os
import re
import shutil
import subprocess
from collections import defaultdict
from pathlib import Path

import browser
import pytest

CLI = os.environ.get("ZDG_CLI", "")
SCRIPT = Path(__file__).resolve().parents[2] / "papers" / "plot_convergence.py"
if not CLI or not os.path.exists(CLI):
    pytest.skip("the zdg CLI was not built", allow_module_level=True)

BROWSER_MISSING = browser.missing_message("the page tests")
if not BROWSER_MISSING:
    from selenium.webdriver.common.action_chains import ActionChains

CONFIG = """title = "convergence page test"
shape = ["ball:10", "ellipse:10,6"]
estimator = ["gauss-area", "dss-length"]
h = "exp:10:20:5"
translations = 2
seed = 7
tolerance = 10
threads = 2
"""
LEVELS = (10, 15, 20)


def published_rows():
    """published.csv rows: TestFig (ellipse, dss-length) a band at the run's three levels and
    one level the run lacks; Flat (ball, gauss-area) a curve (lo = hi); Other a shape the run
    lacks."""
    rows = []
    for i in LEVELS + (40,):
        h = math.exp(-i / 10)
        rows.append(("TestFig", "ellipse:10,6", "dss-length", i, h, 0.5 * h, 0.9 * h))
    for i in LEVELS:
        h = math.exp(-i / 10)
        rows.append(("Flat", "ball:10", "gauss-area", i, h, 2 * h * h, 2 * h * h))
        rows.append(("Other", "flower:20,7,6", "dss-length", i, h, 0.1, 0.2))
    return rows


def converge(config_dir, out, env=None):
    return subprocess.run([CLI, "converge", str(config_dir / "config.toml"), "-o", str(out),
                           "--quiet"], capture_output=True, text=True, env=env)


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Two runs of CONFIG: 'plain' (no published.csv beside the config) and 'paper' (one)."""
    d = tmp_path_factory.mktemp("convergence_page")
    out = {}
    for name in ("plain", "paper"):
        (d / name).mkdir()
        (d / name / "config.toml").write_text(CONFIG)
        if name == "paper":
            with open(d / name / "published.csv", "w", newline="") as f:
                w = csv.writer(f)
                w.writerow(["figure", "shape", "estimator", "i", "h", "lo", "hi"])
                w.writerows(published_rows())
        r = converge(d / name, d / (name + "-out"))
        assert r.returncode == 0, r.stderr
        page = d / (name + "-out") / "convergence.html"
        assert "page:    " + str(page) in r.stdout, r.stdout
        with open(d / (name + "-out") / "results.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        with open(d / (name + "-out") / "summary.json") as f:
            summary = json.load(f)
        out[name] = {"dir": d / (name + "-out"), "rows": rows, "summary": summary}
    return d, out


def series_of(rows):
    """(shape, estimator, norm) in the order of results.csv, with {h: [(translation, value)]}."""
    series = {}
    for r in rows:
        for norm in ("linf", "l2", "mean"):
            v = float(r[norm])
            s = series.setdefault((r["shape"], r["estimator"], norm), defaultdict(list))
            if math.isfinite(v):
                s[float(r["h"])].append((int(r["translation"]), v))
    return series


# --- without a browser ---------------------------------------------------------------------


def test_published_curves_in_the_svg_and_png(runs, tmp_path):
    _, out = runs
    paper, plain = out["paper"]["dir"], out["plain"]["dir"]
    svg = (paper / "convergence.svg").read_text()
    # matplotlib writes each text as a comment beside its glyphs; a hatch is a <pattern>.
    assert "published: TestFig" in svg and "published: Flat" in svg
    assert "Other" not in svg
    assert "<pattern" in svg
    plain_svg = (plain / "convergence.svg").read_text()
    assert "published" not in plain_svg and "<pattern" not in plain_svg
    # The same run drawn without --published: the PNG differs by the published curves alone.
    r = subprocess.run(["/usr/bin/python3", str(SCRIPT), "--csv", str(paper / "results.csv"),
                        "--summary", str(paper / "summary.json"), "--png", str(tmp_path / "a.png"),
                        "--svg", str(tmp_path / "a.svg")], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "published" not in (tmp_path / "a.svg").read_text()
    assert (tmp_path / "a.png").read_bytes() != (paper / "convergence.png").read_bytes()
    assert not (tmp_path / "convergence.html").exists()  # no --html, no page


def test_dir_form_finds_published_beside_the_config(runs, tmp_path):
    _, out = runs
    for name in ("results.csv", "summary.json"):
        shutil.copy(out["paper"]["dir"] / name, tmp_path / name)
    r = subprocess.run(["/usr/bin/python3", str(SCRIPT), str(tmp_path)], capture_output=True,
                       text=True)
    assert r.returncode == 0, r.stderr
    assert "published: TestFig" in (tmp_path / "convergence.svg").read_text()
    page = (tmp_path / "convergence.html").read_text()
    assert '"figure": "TestFig"' in page and '"figure": "Other"' not in page
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "convergence.html", "convergence.png", "convergence.svg", "results.csv", "summary.json"]


def test_a_plot_that_cannot_be_drawn_leaves_no_page(runs, tmp_path):
    d, _ = runs
    # A source directory without papers/plot_convergence.py: the plot, the SVG and the page
    # are given up together, the results are written.
    env = dict(os.environ, ZDG_SOURCE_DIR=str(tmp_path / "no-source"))
    r = converge(d / "paper", tmp_path / "out", env)
    assert r.returncode == 0, r.stderr
    assert "convergence.png, .svg and .html left as they were" in r.stderr
    assert "page:" not in r.stdout
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["results.csv", "summary.json"]


# --- in the browser ------------------------------------------------------------------------


@pytest.fixture(scope="module")
def driver():
    if BROWSER_MISSING:
        pytest.skip(BROWSER_MISSING)
    drv = browser.chromium(1200, 1400)
    yield drv
    drv.quit()


def load(drv, path):
    drv.get("file://" + str(path))
    ready = drv.execute_script("return !!(window.zdgConvergence && window.zdgConvergence.ready)")
    errors = [e for e in drv.get_log("browser") if e["level"] == "SEVERE"]
    assert ready and not errors, errors


def shown(drv, selector):
    """How many elements of selector are rendered (a box on the screen: an element in a hidden
    group has none)."""
    return drv.execute_script("return [...document.querySelectorAll(arguments[0])].filter(e => {"
                              "const r = e.getBoundingClientRect(); return r.width + r.height > 0"
                              "}).length", selector)


def test_page_draws_every_series_and_the_published_curves(runs, driver):
    _, out = runs
    for name, published in (("plain", []), ("paper", ["TestFig", "Flat"])):
        run = out[name]
        load(driver, run["dir"] / "convergence.html")
        expected = series_of(run["rows"])
        page = driver.execute_script("return zdgConvergence.series")
        assert [(s["shape"], s["estimator"], s["norm"]) for s in page] == list(expected)
        drawn = [k for k, per_h in expected.items()
                 if any(v > 0 for values in per_h.values() for _, v in values)]
        assert len(drawn) >= 8, drawn  # the run measured errors: the count below means something
        assert [(s["shape"], s["estimator"], s["norm"]) for s in page if s["drawn"]] == drawn
        assert len(driver.find_elements("css selector", "path.zdg-curve")) == len(drawn)
        got = driver.execute_script("return zdgConvergence.published")
        assert [p["figure"] for p in got] == published
        assert all(p["points"] == len(LEVELS) for p in got)
        assert len(driver.find_elements("css selector", ".zdg-published")) == len(published)
        assert driver.execute_script("return zdgConvergence.visible()") == {
            "series": len(drawn), "published": len(published)}
        assert shown(driver, "path.zdg-curve") == len(drawn)
        legend = driver.find_element("id", "legend").text
        assert ("published: TestFig" in legend) == bool(published)
        # Verdicts: one row per fit of summary.json, the verdict it records.
        fits = run["summary"]["fits"]
        cells = driver.execute_script(
            "return [...document.querySelectorAll('tr.zdg-verdict')].map("
            "r => [...r.cells].map(c => c.textContent))")
        assert len(cells) == len(fits)
        for c, f in zip(cells, fits):
            assert [c[0], c[1]] == [f["shape"], f["estimator"]]
            verdict = "\u2014" if f["pass"] is None else "pass" if f["pass"] else "FAIL"
            assert c[6].startswith(verdict), (c[6], f)


def test_toggles_hide_curves(runs, driver):
    _, out = runs
    run = out["paper"]
    load(driver, run["dir"] / "convergence.html")
    drawn = [s for s in driver.execute_script("return zdgConvergence.series") if s["drawn"]]
    ellipse = sum(s["shape"] == "ellipse:10,6" for s in drawn)
    assert 0 < ellipse < len(drawn)
    # A real click on the shape's checkbox.
    box = driver.find_element("css selector", 'input[data-kind="shape"][data-name="ellipse:10,6"]')
    box.click()
    assert shown(driver, "path.zdg-curve") == len(drawn) - ellipse
    band, flat = driver.find_elements("css selector", ".zdg-published")  # published.csv's order
    assert flat.is_displayed() and not band.is_displayed()  # TestFig is the ellipse's
    box.click()
    assert shown(driver, "path.zdg-curve") == len(drawn)
    # Through the interface: no l_inf curve, no published curve (they are l_inf errors).
    driver.execute_script("zdgConvergence.setVisible('norm', 'linf', false)")
    assert shown(driver, "path.zdg-curve") == sum(s["norm"] != "linf" for s in drawn)
    assert shown(driver, ".zdg-published") == 0
    assert not driver.find_element("css selector", 'input[data-name="linf"]').is_selected()
    driver.execute_script("zdgConvergence.setVisible('estimator', 'gauss-area', false)")
    assert shown(driver, "path.zdg-curve") == sum(
        s["norm"] != "linf" and s["estimator"] != "gauss-area" for s in drawn)


def hover(drv, element):
    ActionChains(drv, duration=0).move_to_element(element).perform()
    hidden, text = drv.execute_script("const t = document.getElementById('tooltip');"
                                      "return [t.hidden, t.textContent]")
    assert not hidden
    h = float(re.search(r"^h = (\S+)$", text, re.M).group(1))
    return text, h


def centres(drv, selector):
    """The elements of selector with the centres of their boxes on the screen."""
    return drv.execute_script(
        "return [...document.querySelectorAll(arguments[0])].map(e => {"
        "const r = e.getBoundingClientRect(); return [e, r.x + r.width / 2, r.y + r.height / 2]})",
        selector)


def error_of(text):
    return float(re.search(r"^error = (\S+)$", text, re.M).group(1))


def test_hover_gives_the_csv_values(runs, driver):
    _, out = runs
    run = out["paper"]
    load(driver, run["dir"] / "convergence.html")
    expected = series_of(run["rows"])
    page = driver.execute_script("return zdgConvergence.series")
    # This series alone (so that no other point lies over the one hovered).
    alone = """const s = zdgConvergence.series[arguments[0]];
        for (const x of zdgConvergence.series)
          for (const kind of ['shape', 'estimator', 'norm'])
            zdgConvergence.setVisible(kind, x[kind], x[kind] === s[kind]);"""
    points_checked = runs_checked = 0
    # The l_inf (worst translation) and l_2 (mean) series of each estimator on one shape.
    for index, s in enumerate(page):
        if not s["drawn"] or s["norm"] == "mean" or s["shape"] != page[0]["shape"]:
            continue
        driver.execute_script(alone, index)
        per_h = expected[(s["shape"], s["estimator"], s["norm"])]
        points = centres(driver, f'g[data-series="{index}"] circle.zdg-point')
        assert len(points) == s["points"]
        for p, _, _ in points:
            text, h = hover(driver, p)
            assert text.startswith(f"{s['shape']} \u00b7 {s['estimator']} \u00b7 "), text
            values = next(v for k, v in per_h.items() if math.isclose(k, h, rel_tol=1e-5))
            if s["norm"] == "linf":  # the worst translation, named
                t, worst = max(values, key=lambda x: x[1])
                assert error_of(text) == pytest.approx(worst, rel=1e-5)
                assert f"translation {t} (the largest of {len(values)} translations)" in text
            else:
                assert error_of(text) == pytest.approx(sum(v for _, v in values) / len(values),
                                                       rel=1e-5)
                assert f"mean of {len(values)} translations" in text
            points_checked += 1
        # The dot of one translation, where no aggregated point covers it.
        for dot, x, y in centres(driver, f'g[data-series="{index}"] circle.zdg-run'):
            if min(math.dist((x, y), (px, py)) for _, px, py in points) < 10:
                continue
            text, h = hover(driver, dot)
            t = int(re.search(r"^translation (\d+)$", text, re.M).group(1))
            values = next(v for k, v in per_h.items() if math.isclose(k, h, rel_tol=1e-5))
            assert error_of(text) == pytest.approx(dict(values)[t], rel=1e-5)
            runs_checked += 1
            break
    assert points_checked >= 8 and runs_checked >= 1, (points_checked, runs_checked)
    # A published point: its band as published.csv has it.
    for kind, n in (("shape", "ellipse:10,6"), ("estimator", "dss-length"), ("norm", "linf")):
        driver.execute_script("zdgConvergence.setVisible(...arguments)", kind, n, True)
    band = {i: (lo, hi) for f, _, _, i, _, lo, hi in published_rows() if f == "TestFig"}
    # The first of its dots that no curve's point covers.
    dot = driver.execute_script("""
        for (const d of document.querySelectorAll('circle.zdg-published-point')) {
          const r = d.getBoundingClientRect();
          if (r.width && document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2) === d)
            return d;
        }
        return null;""")
    assert dot is not None
    text, h = hover(driver, dot)
    assert text.startswith("published: TestFig"), text
    lo, hi = band[round(-10 * math.log(h))]
    got = re.search(r"^band = (\S+) \.\. (\S+)$", text, re.M)
    assert (float(got.group(1)), float(got.group(2))) == (pytest.approx(lo, rel=1e-5),
                                                         pytest.approx(hi, rel=1e-5))
