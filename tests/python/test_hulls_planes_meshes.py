"""Hulls (2D, 3D, disc, ellipse), digital planes, power maps and surface meshes from Python:
each against an independent oracle (brute force, Pick's and Euler's formulas, the chord
theorem's certificate, the command line's own output)."""
import itertools
import json
import os
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import zdg

hyp = pytest.importorskip("hypothesis")
from hypothesis import given, strategies as st  # noqa: E402

CLI = os.environ.get("ZDG_CLI", "")


def orient3(a, b, c, d):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


@given(st.lists(st.tuples(*[st.integers(-2**70, 2**70)] * 3), min_size=4, max_size=25))
def test_3d_hull_supports_every_point_and_satisfies_euler(points):
    h = zdg.hull(points)
    if h["dimension"] < 3:
        return
    verts = h["vertices"]
    assert all(v in points for v in verts)
    edges = 0
    for facet, n in zip(h["facets"], h["normals"]):
        edges += len(facet)
        c = sum(n[i] * verts[facet[0]][i] for i in range(3))
        for p in points:  # every point on the inner side of every facet plane (exact ints)
            assert sum(n[i] * p[i] for i in range(3)) <= c
    assert len(verts) - edges // 2 + len(h["facets"]) == 2
    # 6 x volume: the sum of the signed tetrahedra from vertex 0 over the fan of each facet.
    v0 = verts[0]
    vol6 = 0
    for facet in h["facets"]:
        for k in range(1, len(facet) - 1):
            vol6 += orient3(v0, verts[facet[0]], verts[facet[k]], verts[facet[k + 1]])
    assert abs(vol6) == h["volume6"]


def test_hull_refuses_mixed_dimensions_and_empty():
    with pytest.raises(ValueError, match="mixed"):
        zdg.hull([(0, 0), (1, 2, 3)])
    with pytest.raises(ValueError, match="no point"):
        zdg.hull([])


def lattice_points_in_disc(cx, cy, r):
    pts = []
    for x in range(int(np.floor(cx - r)) - 1, int(np.ceil(cx + r)) + 2):
        for y in range(int(np.floor(cy - r)) - 1, int(np.ceil(cy + r)) + 2):
            if (x - cx) ** 2 + (y - cy) ** 2 <= r * r:
                pts.append((x, y))
    return pts


@given(st.fractions(-5, 5, max_denominator=7), st.fractions(-5, 5, max_denominator=7),
       st.fractions(0, 9, max_denominator=5))
def test_disc_hull_is_the_hull_of_the_lattice_points(cx, cy, r):
    pts = lattice_points_in_disc(cx, cy, r)
    got = zdg.hull_disc(cx, cy, r)["vertices"]
    if not pts:
        assert got == []
        return
    assert sorted(got) == sorted(zdg.hull(pts)["vertices"])


def test_disc_and_ellipse_hulls_accept_ints_fractions_and_text():
    a = zdg.hull_disc(0, 0, 5)["vertices"]
    assert len(a) == 12 and (3, -4) in a  # 12 lattice points on x^2 + y^2 = 25
    assert zdg.hull_disc("0", Fraction(0), "5.0")["vertices"] == a
    e = zdg.hull_ellipse(0, 0, 3, 2)["vertices"]
    assert sorted(e) == sorted(zdg.hull([p for p in itertools.product(range(-3, 4), range(-2, 3))
                                         if 4 * p[0] ** 2 + 9 * p[1] ** 2 <= 36])["vertices"])
    with pytest.raises(TypeError, match="float"):
        zdg.hull_disc(0, 0, 2.5)
    with pytest.raises(ValueError, match="negative radius"):
        zdg.hull_disc(0, 0, -1)
    with pytest.raises(ValueError, match="max_vertices"):
        zdg.hull_disc(0, 0, 10**12, max_vertices=10)
    # Issue #41: the library's default bound (10^8, as on the command line and in zdg serve).
    with pytest.raises(ValueError, match="more than the vertex bound 100000000"):
        zdg.hull_disc(0, 0, 10**15)
    with pytest.raises(ValueError, match="more than the vertex bound 100000000"):
        zdg.hull_ellipse(0, 0, 10**15, 10**15)


def test_probe_plane_step_bounds():
    """Issue #41: H past its proven step bound is refused before any work; R stops at the
    default budget of 10^6 steps (about a second) naming the bound."""
    with pytest.raises(ValueError, match=r"\|\|N\|\|_1 - 3 = 2000000016 steps"):
        zdg.probe_plane(1000000007, 1000000009, 3, algorithm="h")
    with pytest.raises(ValueError, match="not ended after 1000000 steps"):
        zdg.probe_plane(1000000007, 1000000009, 3)
    assert zdg.probe_plane(2, 6, 15, algorithm="h", max_steps=20)["normal"] == (2, 6, 15)
    with pytest.raises(ValueError, match="more than max_steps 19"):
        zdg.probe_plane(2, 6, 15, algorithm="h", max_steps=19)


@given(st.integers(-30, 30), st.integers(-30, 30), st.integers(-30, 30))
def test_probe_plane_returns_the_plane_normal(a, b, c):
    from math import gcd
    if a == 0 or b == 0 or c == 0 or gcd(gcd(a, b), c) != 1:
        with pytest.raises(ValueError):
            zdg.probe_plane(a, b, c)
        return
    for alg in ("h", "r"):
        r = zdg.probe_plane(a, b, c, algorithm=alg)
        assert r["normal"] == (a, b, c)
        assert r["steps"] <= abs(a) + abs(b) + abs(c) - 3
    assert zdg.probe_plane(a, b, c)["reduced_basis"]


def test_recognize_plane_certificate_and_counterexample():
    pts = [(x, y, (x + 2 * y) // 3) for x in range(6) for y in range(6)]
    r = zdg.recognize_plane(pts)
    assert r["is_plane"]
    n, mu, omega = r["normal"], r["mu"], r["omega"]
    assert omega == max(abs(v) for v in n)
    assert all(mu <= sum(n[i] * p[i] for i in range(3)) < mu + omega for p in pts)
    assert not zdg.recognize_plane(list(itertools.product((0, 1), repeat=3)))["is_plane"]


def brute_power_map(weights, p):
    sites = [tuple(s) for s in np.argwhere(weights > 0)]
    best_power = np.empty(weights.shape, dtype=object)
    for x in np.ndindex(*weights.shape):
        best_power[x] = min(sum(abs(int(a) - int(b)) ** p for a, b in zip(x, s)) - int(weights[s])
                            for s in sites)
    return best_power


@pytest.mark.parametrize("metric,p", [("l2", 2), ("l1", 1), ("l3", 3)])
def test_power_map_minimises_the_power(metric, p):
    rng = np.random.default_rng(5)
    w = np.where(rng.random((7, 9)) < 0.15, rng.integers(1, 12, (7, 9)), 0).astype(np.int64)
    w[3, 4] = 5
    site, negative = zdg.power_map(w, metric=metric)
    best = brute_power_map(w, p)
    for x in np.ndindex(*w.shape):
        s = np.unravel_index(site[x], w.shape)
        assert w[s] > 0
        power = sum(abs(int(a) - int(b)) ** p for a, b in zip(x, s)) - int(w[s])
        assert power == best[x]
        assert bool(negative[x]) == (power < 0)
    with pytest.raises(ValueError):
        zdg.power_map(np.zeros((3, 3), dtype=np.int64))  # no site


def edges_of(faces):
    count = {}
    for f in faces:
        for i in range(len(f)):
            e = tuple(sorted((int(f[i]), int(f[(i + 1) % len(f)]))))
            count[e] = count.get(e, 0) + 1
    return count


@pytest.mark.parametrize("mesh", ["primal", "marching-cubes"])
def test_surface_mesh_of_a_ball_is_a_closed_sphere(mesh):
    z, y, x = np.mgrid[:14, :14, :14]
    ball = ((x - 6.5) ** 2 + (y - 6.2) ** 2 + (z - 6.8) ** 2 <= 25).astype(np.uint8)
    s = zdg.surface(ball, mesh=mesh)
    v, f = s["vertices"], s["faces"]
    assert v.shape[1] == 3 and f.shape[1] == (4 if mesh == "primal" else 3)
    edges = edges_of(f)
    assert set(edges.values()) == {2}  # closed: every edge in two faces
    assert len(v) - len(edges) + len(f) == 2  # Euler characteristic of a sphere
    if mesh == "primal":
        assert len(f) == len(zdg.surfels(ball)["codes"])  # one quad per surfel
    # Spacing scales the vertices (given as z, y, x; vertices are x, y, z).
    t = zdg.surface(ball, mesh=mesh, spacing=(2.0, 1.0, 0.5))
    assert np.allclose(t["vertices"] - t["vertices"].min(axis=0),
                       (v - v.min(axis=0)) * np.array([0.5, 1.0, 2.0]))
    with pytest.raises(ValueError, match="spacing"):
        zdg.surface(ball, spacing=(1, 0, 1))
    with pytest.raises(ValueError, match="mesh"):
        zdg.surface(ball, mesh="dual")


@pytest.mark.skipif(not CLI, reason="needs the zdg command line (run by ctest)")
def test_surface_mesh_equals_the_command_lines_ply(tmp_path):
    z, y, x = np.mgrid[:10, :12, :11]
    vol = (((x - 5) ** 2 / 16 + (y - 6) ** 2 / 25 + (z - 4.5) ** 2 / 9) <= 1).astype(np.uint8)
    np.save(tmp_path / "v.npy", vol)
    subprocess.run([CLI, "surface", str(tmp_path / "v.npy"), "-o", str(tmp_path / "m.ply"),
                    "--quiet"], check=True, capture_output=True)
    text = (tmp_path / "m.ply").read_bytes()
    header_end = text.index(b"end_header\n") + len(b"end_header\n")
    header = text[:header_end].decode()
    nv = int(header.split("element vertex ")[1].split()[0])
    nf = int(header.split("element face ")[1].split()[0])
    s = zdg.surface(vol)
    assert (nv, nf) == (len(s["vertices"]), len(s["faces"]))


def test_surface_estimates_are_the_ii_estimates_per_face():
    z, y, x = np.mgrid[:20, :20, :20]
    ball = ((x - 9.5) ** 2 + (y - 10.1) ** 2 + (z - 9.7) ** 2 <= 49).astype(np.uint8)
    s = zdg.surface(ball, estimate="principal", h=1.0, radius=3.0)
    ii = zdg.ii_curvature(ball, h=1.0, radius=3.0, principal=True)
    assert len(s["faces"]) == len(ii["mean"])  # face f is surfel f
    for key in ("mean", "k1", "k2", "gaussian", "normal"):
        assert np.array_equal(s[key], ii[key]), key
    with pytest.raises(ValueError, match="primal"):
        zdg.surface(ball, mesh="marching-cubes", estimate="mean", radius=3.0)
    with pytest.raises(ValueError, match="radius"):
        zdg.surface(ball, estimate="mean")


def test_skeleton_is_the_curve_thinning_and_keeps_the_topology():
    z, y, x = np.mgrid[:16, :16, :16]
    torus = ((np.sqrt((x - 7.5) ** 2 + (y - 7.5) ** 2) - 5) ** 2 + (z - 7.5) ** 2 <= 4)
    sk = zdg.skeleton(torus.astype(np.uint8))
    assert np.array_equal(sk, zdg.thinning(torus.astype(np.uint8), skeleton="curve"))
    assert zdg.betti_numbers(sk)["betti"] == zdg.betti_numbers(torus)["betti"] == (1, 1, 0)
    assert 0 < sk.sum() < torus.sum() / 2


def test_halfplane_hull_of_a_triangle_and_of_unbounded_regions():
    r = zdg.hull_halfplanes([(-1, 0, 0), (0, -1, 0), (1, 1, "7/2")])
    assert r["region"] == "bounded"
    assert sorted(r["vertices"]) == [(0, 0), (0, 3), (3, 0)]
    assert zdg.hull_halfplanes([(-1, 0, 0)])["region"] == "unbounded"
    assert zdg.hull_halfplanes([(1, 0, -1), (-1, 0, -1)])["region"] == "empty"
    with pytest.raises(ValueError):
        zdg.hull_halfplanes([(1, 2)])
