"""zdg.view: the viewer page of zdg surface --html made from numpy arrays (zdg.mesh_html, the
C++ page), shown inline by Jupyter as a sandboxed iframe and saved atomically. The page's
embedded data are decoded here and compared with the arrays given; bad input is one ValueError
line. In headless Chromium (when chromium, chromium-driver and python3-selenium are installed;
else skipped, or failed under ZDG_REQUIRE_BROWSER=1) the saved page and the inline frame each
report the face count through window.zdgViewer."""
import base64
import html
import html.parser
import json
import os
import shutil
import time

import numpy as np
import pytest

import zdg

# A unit cube: 8 vertices, 6 quads counter-clockwise from outside.
CUBE_V = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
CUBE_F = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2],
                   [1, 3, 7, 5]])


def page_data(page):
    """The JSON object the page embeds, with its base64 arrays decoded."""
    start = page.index('<script id="zdg-data" type="application/json">')
    start = page.index(">", start) + 1
    d = json.loads(page[start:page.index("</script>", start)])
    d["positions"] = np.frombuffer(base64.b64decode(d["positions"]), "<f4").reshape(-1, 3)
    d["indices"] = np.frombuffer(base64.b64decode(d["indices"]), "<u4").reshape(d["faces"], -1)
    for f in d["fields"]:
        f["values"] = np.frombuffer(base64.b64decode(f["values"]), "<f4")
    if "normals" in d:
        d["normals"] = np.frombuffer(base64.b64decode(d["normals"]), "i1").reshape(-1, 3)
    return d


@pytest.fixture(scope="module")
def ball():
    z, y, x = np.mgrid[:18, :18, :18] - 8.5
    return ((x ** 2 + y ** 2 + (1.2 * z) ** 2) <= 7 ** 2).astype(np.uint8)


def test_surface_result_carries_the_pages_fields_and_normals(ball):
    s = zdg.surface(ball, estimate="mean", radius=3)
    nf = len(s["faces"])
    assert set(s["fields"]) == {"ii-mean"}
    assert np.array_equal(s["fields"]["ii-mean"], s["mean"])
    assert s["face_normals"].shape == (nf, 3)
    # Without estimates the primal faces carry the surfels' elementary (axis) normals.
    plain = zdg.surface(ball)
    assert plain["fields"] == {}
    n = plain["face_normals"]
    assert np.array_equal(np.abs(n).sum(axis=1), np.ones(nf))
    # The marching-cubes mesh has no face normals (its normals are per vertex).
    assert "face_normals" not in zdg.surface(ball, mesh="marching-cubes")


def test_view_of_a_surface_result_is_the_surface_page(ball):
    s = zdg.surface(ball, estimate="principal", radius=3)
    v = zdg.view(s, field="ii-k2", title="a ball")
    nf = len(s["faces"])
    assert isinstance(v, zdg.Viewer) and v.faces == nf and v.title == "a ball"
    assert set(v.fields) == set(s["fields"]) and len(v.fields) >= 2
    for name in s["fields"]:
        assert json.dumps(name) in v.html
    assert f'"faces":{nf}' in v.html and "window.zdgViewer" in v.html
    d = page_data(v.html)
    assert d["title"] == "a ball" and d["field"] == "ii-k2" and d["face_size"] == 4
    assert np.array_equal(d["positions"], s["vertices"].astype("<f4"))
    assert np.array_equal(d["indices"], s["faces"])
    for f in d["fields"]:
        assert np.array_equal(f["values"], s["fields"][f["name"]].astype("<f4"))
    unit = s["face_normals"] / np.linalg.norm(s["face_normals"], axis=1)[:, None]
    # Unit vectors times 127, rounded (ties may round either way).
    assert np.abs(d["normals"] - np.rint(127 * unit)).max() <= 1
    assert "<title>a ball</title>" in v.html
    assert "a ball" in repr(v) and str(nf) in repr(v)


def test_view_of_arrays_in_any_layout_and_type():
    fields = {"height": CUBE_V[CUBE_F].mean(axis=1)[:, 2], "index": np.arange(6, dtype=np.int32)}
    normals = np.array([[0, 0, -1], [0, 0, 1], [0, -1, 0], [0, 1, 0], [-1, 0, 0], [1, 0, 0]])
    # F-ordered float32 vertices, uint16 faces, a strided field: converted, not misread.
    v = zdg.view((np.asfortranarray(CUBE_V, dtype=np.float32), CUBE_F.astype(np.uint16),
                  {"height": fields["height"], "index": np.arange(12)[::2]}, normals))
    d = page_data(v.html)
    assert v.faces == 6 and v.fields == ("height", "index") and d["faces"] == 6
    assert np.array_equal(d["positions"], CUBE_V) and np.array_equal(d["indices"], CUBE_F)
    assert [f["name"] for f in d["fields"]] == ["height", "index"]
    assert np.array_equal(d["fields"][1]["values"], np.arange(0, 12, 2))
    assert np.array_equal(d["normals"], 127 * normals)
    # A dict mesh, and lists; no fields, no normals; triangles.
    tri = zdg.view({"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "faces": [[0, 1, 2]]})
    d = page_data(tri.html)
    assert tri.fields == () and d["fields"] == [] and "normals" not in d and d["face_size"] == 3
    # Non-finite field values are allowed (the page draws them as 'no value').
    zdg.view((CUBE_V, CUBE_F, {"f": np.array([np.nan, 1, 2, 3, np.inf, 5])}))


def test_repr_html_is_a_sandboxed_iframe_holding_the_page():
    v = zdg.view((CUBE_V, CUBE_F, {"a<b": np.arange(6.0)}), title='"quoted" & <tagged>')
    r = v._repr_html_()
    assert r.startswith("<iframe ") and r.endswith("</iframe>")

    class Frames(html.parser.HTMLParser):
        def __init__(self):
            super().__init__()
            self.frames = []

        def handle_starttag(self, tag, attrs):
            self.frames.append((tag, dict(attrs)))

    p = Frames()
    p.feed(r)
    assert len(p.frames) == 1, "the page's markup leaked out of the srcdoc attribute"
    tag, attrs = p.frames[0]
    assert tag == "iframe" and attrs["sandbox"] == "allow-scripts"
    assert attrs["srcdoc"] == v.html and attrs["title"] == v.title
    assert "height:520px" in attrs["style"]
    assert "<title>&quot;quoted&quot; &amp; &lt;tagged&gt;</title>" in v.html


def test_save_is_atomic_and_refuses_to_overwrite(tmp_path):
    v = zdg.view((CUBE_V, CUBE_F))
    path = tmp_path / "cube.html"
    assert v.save(path) == path
    assert path.read_text(encoding="utf-8") == v.html
    other = zdg.view((CUBE_V, CUBE_F, {"a": np.arange(6.0)}))
    with pytest.raises(FileExistsError, match="cube.html: exists .*force=True"):
        other.save(path)
    assert path.read_text(encoding="utf-8") == v.html
    other.save(str(path), force=True)
    assert path.read_text(encoding="utf-8") == other.html
    with pytest.raises(ValueError, match=r"cube.png: the viewer page is an .html file"):
        v.save(tmp_path / "cube.png")
    with pytest.raises(OSError, match="does not exist"):
        v.save(tmp_path / "no-such-folder" / "cube.html")
    assert sorted(os.listdir(tmp_path)) == ["cube.html"]  # no staging file left


@pytest.mark.parametrize("mesh, kwargs, message", [
    ((CUBE_V[:, :2], CUBE_F), {}, r"view: vertices has shape \(8, 2\), not \(n, 3\)"),
    ((CUBE_V, CUBE_F.astype(float)), {}, r"view: faces must hold integers, not float64"),
    ((CUBE_V, CUBE_F.ravel()), {}, r"view: faces has shape \(24,\), not \(n, n\)"),
    ((CUBE_V, CUBE_F[:, :2]), {}, r"faces of 2 vertices \(at least 3 needed\)"),
    ((CUBE_V, CUBE_F + 1), {}, r"mesh: face 1 uses vertex 8 of 8"),
    ((CUBE_V, -CUBE_F), {}, r"mesh: face 0 uses vertex -2 of 8"),
    ((np.where(np.arange(24).reshape(8, 3) == 10, np.nan, CUBE_V), CUBE_F), {},
     r"view: vertex 3 is \(1\.0+, nan, 0\.0+\), not finite"),
    ((CUBE_V, CUBE_F, {"a": np.arange(5.0)}), {}, r"view: field 'a' has shape \(5,\), not \(6,\)"),
    ((CUBE_V, CUBE_F, {"a": np.array(["x"] * 6)}), {}, r"view: field 'a' must hold numbers"),
    ((CUBE_V, CUBE_F, {1: np.arange(6.0)}), {}, r"view: a field name is 1, not a str"),
    ((CUBE_V, CUBE_F, None, np.full((6, 3), np.inf)), {}, r"view: face normal 0 is \(inf"),
    ((CUBE_V, CUBE_F, None, np.ones((5, 3))), {}, r"face normals has shape \(5, 3\), not \(6, 3\)"),
    ((CUBE_V, CUBE_F), {"max_faces": 5},
     r"view: the page would hold 6 faces, more than max_faces=5"),
    ((CUBE_V, CUBE_F), {"max_faces": 0}, r"view: max_faces is 0, not positive"),
    ((CUBE_V, CUBE_F, {"a": np.arange(6.0)}), {"field": "b"},
     r"the field 'b' is not on the mesh \(a\)"),
    ({"vertices": CUBE_V}, {}, r"view: the mesh dict has no 'faces' \(keys: vertices\)"),
])
def test_bad_input_is_one_clear_value_error(mesh, kwargs, message):
    with pytest.raises(ValueError, match=message) as e:
        zdg.view(mesh, **kwargs)
    assert "\n" not in str(e.value)


def test_what_is_not_a_mesh_is_a_type_error():
    with pytest.raises(TypeError, match="expected the result of zdg.surface"):
        zdg.view([CUBE_V, CUBE_F])
    with pytest.raises(TypeError, match="got str"):
        zdg.view("mesh.ply")


# --- in a browser ---------------------------------------------------------------------------

def browser_driver():
    missing = [name for name, ok in (("chromium", shutil.which("chromium")),
                                      ("chromium-driver", shutil.which("chromedriver")))
               if not ok]
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        missing.append("python3-selenium")
    if missing:
        message = "the browser checks need: apt-get install " + " ".join(missing)
        if os.environ.get("ZDG_REQUIRE_BROWSER") == "1":
            pytest.fail(message + " (ZDG_REQUIRE_BROWSER=1)")
        pytest.skip(message)
    opts = webdriver.ChromeOptions()
    opts.binary_location = shutil.which("chromium")
    for a in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=960,640",
              "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-extensions"):
        opts.add_argument(a)
    return webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=opts)


def viewer_faces(drv):
    """window.zdgViewer.faces once the page is ready (in the current frame)."""
    for _ in range(300):
        if drv.execute_script("return !!(window.zdgViewer && window.zdgViewer.ready)"):
            return drv.execute_script("return window.zdgViewer.faces")
        time.sleep(0.05)
    raise AssertionError("the viewer did not become ready")


def test_saved_page_and_inline_frame_in_chromium(ball, tmp_path):
    s = zdg.surface(ball, estimate="mean", radius=3)
    v = zdg.view(s)
    v.save(tmp_path / "ball.html")
    # A notebook-like host page: the inline output inside a document of its own.
    (tmp_path / "host.html").write_text("<!doctype html><html><body><p>output</p>"
                                        + v._repr_html_() + "</body></html>", encoding="utf-8")
    drv = browser_driver()
    try:
        drv.get((tmp_path / "ball.html").as_uri())
        assert viewer_faces(drv) == len(s["faces"])
        drv.get((tmp_path / "host.html").as_uri())
        frame = drv.find_element("css selector", "iframe.zdg-viewer")
        drv.switch_to.frame(frame)
        assert viewer_faces(drv) == len(s["faces"])
        drv.switch_to.default_content()
        # The frame's script stays in the frame: the host window has no viewer object.
        assert drv.execute_script("return typeof window.zdgViewer") == "undefined"
    finally:
        drv.quit()
