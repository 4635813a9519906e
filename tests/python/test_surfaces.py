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
