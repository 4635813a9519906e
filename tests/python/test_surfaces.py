"""Boundary surfels and integral-invariant curvature of numpy volumes."""
import numpy as np
import pytest

import zdg

hyp = pytest.importorskip("hypothesis")
from hypothesis import given, strategies as st  # noqa: E402
from hypothesis.extra.numpy import arrays  # noqa: E402


@given(arrays(np.bool_, st.tuples(st.integers(1, 6), st.integers(1, 6), st.integers(1, 6))))
def test_surfels_are_the_inside_outside_face_pairs(volume):
    """One surfel per (object voxel, 6-neighbour outside the object or the array) pair, at the
    middle of their common face; codes sorted."""
    r = zdg.surfels(volume)
    padded = np.pad(volume, 1)
    expected = set()
    for axis in range(3):  # numpy axis 0 is z, 2 is x
        for step in (-1, 1):
            outer = np.roll(padded, -step, axis=axis)
            inside = padded & ~outer
            for z, y, x in np.argwhere(inside[1:-1, 1:-1, 1:-1]):
                p = [float(x), float(y), float(z)]
                p[2 - axis] += 0.5 * step
                expected.add(tuple(p))
    assert len(r["codes"]) == len(expected)
    assert set(map(tuple, r["centres"].tolist())) == expected
    assert np.all(np.diff(r["codes"].astype(np.int64)) > 0) if len(r["codes"]) > 1 else True


def ball(radius, h):
    """The Gauss digitization of the ball of the given radius at grid step h."""
    n = int(np.ceil(radius / h)) + 2
    c = np.arange(-n, n + 1) * h
    z, y, x = np.meshgrid(c, c, c, indexing="ij")
    return (x * x + y * y + z * z <= radius * radius).astype(np.uint8)


def test_ii_curvature_of_a_ball_converges_to_one_over_the_radius():
    """Mean curvature of the sphere of radius 1 is 1, principal curvatures 1 and 1 (CVIU
    2014: II estimates converge in O(h^{1/3}) with R = k h^{1/3}); at h = 0.1 their averages
    are within 10 %. The mean curvature alone (ball-volume estimator) and the mean of the
    principal ones (covariance estimator) are two estimators of H."""
    h = 0.1
    r = zdg.ii_curvature(ball(1.0, h), h=h, radius=3 * h ** (1 / 3) / 2, principal=True)
    assert abs(float(np.mean(r["mean"])) - 1.0) < 0.1
    assert abs(float(np.median(r["k1"])) - 1.0) < 0.15 and abs(float(np.median(r["k2"])) - 1.0) < 0.15
    assert np.all(r["k1"] <= r["k2"])
    assert np.allclose(np.linalg.norm(r["normal"], axis=1), 1.0)
    # Outward normals: along the centre direction (the ball is centred in the array).
    n = ball(1.0, h).shape[0]
    d = r["centres"] - (n - 1) / 2
    assert np.all(np.einsum("ij,ij->i", d, r["normal"]) > 0)
    assert np.array_equal(r["codes"], zdg.surfels(ball(1.0, h))["codes"])
    mean_only = zdg.ii_curvature(ball(1.0, h), h=h, radius=3 * h ** (1 / 3) / 2)
    assert abs(float(np.mean(mean_only["mean"])) - 1.0) < 0.1


def test_bad_input():
    with pytest.raises(ValueError):
        zdg.surfels(np.ones((3, 3), dtype=np.uint8))
    with pytest.raises(ValueError):
        zdg.ii_curvature(np.ones((3, 3, 3), dtype=np.uint8), h=1, radius=-1)


@given(arrays(np.bool_, st.tuples(st.integers(1, 8), st.integers(1, 8))))
def test_contour_signed_areas_add_up_to_the_pixels(image):
    """Green's theorem on zdg.contour: the signed areas of the contours (holes negative) add
    up to the pixel count; b0 outer contours, b1 holes; each chain closes (its steps sum to 0)."""
    r = zdg.contour(image.astype(np.uint8))
    assert sum(c["pixels"] for c in r["contours"]) == int(image.sum())
    assert sum(c["kind"] == "outer" for c in r["contours"]) == r["betti"][0]
    assert sum(c["kind"] == "hole" for c in r["contours"]) == r["betti"][1]
    steps = np.array([(1, 0), (0, 1), (-1, 0), (0, -1)])
    for c in r["contours"]:
        assert np.all(steps[c["codes"]].sum(axis=0) == 0)
    assert r["linels"] == sum(len(c["codes"]) for c in r["contours"])


def test_contour_estimates_and_the_surface_topology():
    y, x = np.mgrid[:60, :60]
    disc = (((x - 29.5) ** 2 + (y - 29.5) ** 2) <= 20 ** 2).astype(np.uint8)
    r = zdg.contour(disc, estimates=["ii-curvature", "mlp-length", "gauss-area", "bc-tangent"],
                    radius="12v")
    (c,) = r["contours"]
    assert abs(c["mlp_length"] - 2 * np.pi * 20) < 0.05 * 2 * np.pi * 20
    assert r["gauss_area"] == int(disc.sum())
    # the integral invariant at a kernel of 12 pixels on a disc of radius 20: within 30% of 1/20
    assert abs(np.nanmean(c["ii_curvature"]) - 1 / 20) < 0.015
    assert c["bc_tangent"].shape == (len(c["codes"]), 2)
    with pytest.raises(ValueError, match="unknown estimator 'nope'"):
        zdg.contour(disc, estimates=["nope"])
    z, y, x = np.mgrid[:20, :20, :20]
    ball = (((x - 9.5) ** 2 + (y - 9.5) ** 2 + (z - 9.5) ** 2) <= 64).astype(np.uint8)
    s = zdg.surface(ball)
    assert s["betti"] == (1, 0, 0) and s["surfaces"] == 1 and s["object_components"] == 1


def sphere_points(n, radius, seed):
    """n points uniform on the sphere of the given radius about the origin, with unit normals."""
    rng = np.random.default_rng(seed)
    u = rng.normal(size=(n, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    return radius * u, u


@pytest.mark.parametrize("method", ["hoppe", "winding", "imls"])
def test_reconstruct_a_sphere_from_points(method):
    """The reconstruction of sphere samples is one ball (Betti numbers 1, 0, 0 of the solid) whose mesh
    vertices lie within a grid step of the sphere; the field is negative at the centre."""
    p, n = sphere_points(2000, 1.0, 3)
    r = zdg.reconstruct(p, n, h=0.1, method=method)
    assert r["betti"] == (1, 0, 0)
    assert r["normals"] == "given"
    d = np.abs(np.linalg.norm(r["vertices"], axis=1) - 1)
    assert d.max() < 0.1
    assert r["faces"].shape[1] == 3 and r["faces"].max() < len(r["vertices"])
    centre = tuple(-np.array(r["lower"]))  # the sample h * 0
    assert r["field"][centre] < 0


def test_reconstruct_estimates_missing_normals_and_refuses_bad_points():
    p, _ = sphere_points(1500, 1.0, 4)
    r = zdg.reconstruct(p, h=0.1)
    assert r["normals"] == "estimated"
    assert r["betti"] == (1, 0, 0)
    bad = p.copy()
    bad[5] = bad[2]
    with pytest.raises(ValueError, match="repeats point 2"):
        zdg.reconstruct(bad, h=0.1)
    with pytest.raises(ValueError, match=r"not \(n, 3\)"):
        zdg.reconstruct(p[:, :2], h=0.1)


def crossed_voxels(shape, origin, direction, den):
    """The voxels (x, y, z) of the array's box that the line (origin + t direction) / den crosses
    over a positive length, in order: every face-plane parameter, and the voxel of each piece's
    midpoint (exact fractions)."""
    from fractions import Fraction as F
    n = (shape[2], shape[1], shape[0])
    lo, hi, cuts = None, None, []
    for a in range(3):
        o, d = F(origin[a], den), F(direction[a], den)
        if d == 0:
            if not (-F(1, 2) <= o < n[a] - F(1, 2)):
                return []
            continue
        ts = sorted([(F(-1, 2) - o) / d, (n[a] - F(1, 2) - o) / d])
        lo = ts[0] if lo is None else max(lo, ts[0])
        hi = ts[1] if hi is None else min(hi, ts[1])
        cuts += [(k - F(1, 2) - o) / d for k in range(n[a] + 1)]
    if not lo < hi:
        return []
    ts = sorted({lo, hi} | {t for t in cuts if lo < t < hi})
    out = []
    for t0, t1 in zip(ts, ts[1:]):
        t = (t0 + t1) / 2
        out.append(tuple(int((F(origin[a], den) + t * F(direction[a], den) + F(1, 2)) // 1)
                         for a in range(3)))
    return out


@given(arrays(np.bool_, st.tuples(st.integers(1, 6), st.integers(1, 6), st.integers(1, 6))),
       st.tuples(*[st.integers(-12, 40)] * 3), st.tuples(*[st.integers(-3, 3)] * 3),
       st.integers(1, 4), st.sampled_from(["svo", "dag", "ssvdag"]))
def test_dag_ray_hits_are_the_set_voxels_the_line_crosses(volume, origin, direction, den, kind):
    if direction == (0, 0, 0):
        direction = (1, 0, 0)
    hits = zdg.dag_ray_hits(volume, origin, direction, den, kind=kind)
    want = [v for v in crossed_voxels(volume.shape, origin, direction, den)
            if volume[v[2], v[1], v[0]]]
    assert [v for v, _ in hits] == want
    assert all(axis in (0, 1, 2) for _, axis in hits)
    assert zdg.dag_ray_hits(volume, origin, direction, den, kind=kind, max_hits=1) == hits[:1]


@given(arrays(np.bool_, st.tuples(st.integers(1, 9), st.integers(1, 9), st.integers(1, 9))))
def test_voxel_dag_leaves_are_the_occupied_and_the_distinct_bricks(volume):
    """svo: one leaf per non-empty 4^3 brick; dag: one per distinct brick content."""
    side = 4
    while side < max(volume.shape):
        side *= 2
    padded = np.zeros((side, side, side), dtype=bool)
    padded[:volume.shape[0], :volume.shape[1], :volume.shape[2]] = volume
    bricks = [padded[z:z + 4, y:y + 4, x:x + 4].tobytes()
              for z in range(0, side, 4) for y in range(0, side, 4) for x in range(0, side, 4)
              if padded[z:z + 4, y:y + 4, x:x + 4].any()]
    svo, dag = zdg.voxel_dag(volume, kind="svo"), zdg.voxel_dag(volume, kind="dag")
    assert svo["voxels"] == dag["voxels"] == int(volume.sum())
    assert svo["leaves"] == len(bricks) == dag["svo_leaves"]
    assert dag["leaves"] == len(set(bricks))
    assert zdg.voxel_dag(volume)["bytes"] <= dag["bytes"] <= svo["bytes"]


def test_voxel_dag_bad_input():
    with pytest.raises(ValueError, match="3D"):
        zdg.voxel_dag(np.ones((3, 3), dtype=bool))
    with pytest.raises(ValueError, match="expected svo, dag or ssvdag"):
        zdg.voxel_dag(np.ones((3, 3, 3), dtype=bool), kind="octree")
    with pytest.raises(ValueError, match="direction is zero"):
        zdg.dag_ray_hits(np.ones((3, 3, 3), dtype=bool), (0, 0, 0), (0, 0, 0))
