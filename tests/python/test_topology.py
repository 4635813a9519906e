"""Connected components, Betti numbers and thinning of numpy volumes: known shapes, scipy's
labelling as the oracle for components, and the theorem that thinning preserves topology."""
import numpy as np
import pytest

import zdg

ndimage = pytest.importorskip("scipy.ndimage")
hyp = pytest.importorskip("hypothesis")
from hypothesis import given, strategies as st  # noqa: E402
from hypothesis.extra.numpy import arrays  # noqa: E402


def cube(n=7):
    a = np.zeros((n, n, n), dtype=np.uint8)
    a[1:-1, 1:-1, 1:-1] = 1
    return a


def test_betti_numbers_of_known_shapes():
    solid = cube()
    assert zdg.betti_numbers(solid) == {"betti": (1, 0, 0), "euler": 1, "adjacency": "26,6"}
    hollow = cube()
    hollow[3, 3, 3] = 0  # a cavity
    assert zdg.betti_numbers(hollow)["betti"] == (1, 0, 1)
    ring = cube()
    ring[:, 2:5, 2:5] = 0  # a tunnel through the cube along z: a solid torus
    assert zdg.betti_numbers(ring) == {"betti": (1, 1, 0), "euler": 0, "adjacency": "26,6"}
    two = np.zeros((5, 12, 5), dtype=bool)
    two[1:4, 1:4, 1:4] = two[1:4, 7:10, 1:4] = True
    assert zdg.betti_numbers(two)["betti"] == (2, 0, 0)
    annulus = np.zeros((9, 9), dtype=np.uint8)
    annulus[1:8, 1:8] = 1
    annulus[3:6, 3:6] = 0
    assert zdg.betti_numbers(annulus) == {"betti": (1, 1), "euler": 0, "adjacency": "8,4"}
    # A diagonal pair of voxels: one component for 26-adjacency, two for 6.
    diag = np.zeros((4, 4, 4), dtype=np.uint8)
    diag[1, 1, 1] = diag[2, 2, 2] = 1
    assert zdg.betti_numbers(diag)["betti"][0] == 1
    assert zdg.betti_numbers(diag, "6,26")["betti"][0] == 2


STRUCTURES = {4: ndimage.generate_binary_structure(2, 1), 8: ndimage.generate_binary_structure(2, 2),
              6: ndimage.generate_binary_structure(3, 1), 18: ndimage.generate_binary_structure(3, 2),
              26: ndimage.generate_binary_structure(3, 3)}

volumes = st.one_of(
    arrays(np.bool_, st.tuples(st.integers(1, 9), st.integers(1, 9))),
    arrays(np.bool_, st.tuples(st.integers(1, 6), st.integers(1, 6), st.integers(1, 6))))


@given(volumes, st.data())
def test_components_equal_scipy_label(image, data):
    """Same partition of the object as scipy.ndimage.label with the matching structure;
    labels numbered by decreasing size; sizes and border flags consistent with the labels."""
    k = data.draw(st.sampled_from([4, 8] if image.ndim == 2 else [6, 18, 26]))
    labels, sizes, border = zdg.connected_components(image, k)
    ref, count = ndimage.label(image, structure=STRUCTURES[k])
    assert labels.shape == image.shape and labels.dtype == np.uint32
    assert len(sizes) == count
    assert np.array_equal(labels == 0, ~image)
    # Same partition: the pairs (ours, scipy's) are a bijection.
    pairs = set(zip(labels[image].tolist(), ref[image].tolist()))
    assert len(pairs) == count
    assert list(sizes) == [int((labels == i + 1).sum()) for i in range(count)]
    assert list(sizes) == sorted(sizes, reverse=True)
    for i in range(count):
        comp = labels == i + 1
        edge = np.zeros_like(comp)
        for ax in range(image.ndim):
            idx = [slice(None)] * image.ndim
            idx[ax] = 0
            edge[tuple(idx)] = True
            idx[ax] = -1
            edge[tuple(idx)] = True
        assert bool(border[i]) == bool((comp & edge).any())


@given(volumes)
def test_betti_zero_counts_components_and_euler_poincare(image):
    """b0 = number of object components; chi = alternating sum of the Betti numbers."""
    r = zdg.betti_numbers(image)
    k = 8 if image.ndim == 2 else 26
    assert r["betti"][0] == ndimage.label(image, structure=STRUCTURES[k])[1]
    assert r["euler"] == sum((-1) ** i * b for i, b in enumerate(r["betti"]))


@given(volumes, st.sampled_from(["critical-kernel", "sequential"]))
def test_thinning_preserves_topology(image, method):
    """Theorem: deleting simple points (sequentially, or a critical kernel in parallel) keeps
    the homotopy type: same Betti numbers, and the skeleton is a subset of the object."""
    skel = zdg.thinning(image, method=method)
    assert skel.shape == image.shape and skel.dtype == np.uint8
    assert not (skel.astype(bool) & ~image).any()
    assert zdg.betti_numbers(skel)["betti"] == zdg.betti_numbers(image)["betti"]


def test_ultimate_skeleton_of_a_solid_cube_is_one_point():
    assert int(zdg.thinning(cube(9)).sum()) == 1
    assert int(zdg.thinning(cube(9), method="sequential").sum()) == 1


def test_bad_input():
    with pytest.raises(ValueError, match="adjacency|pair"):
        zdg.betti_numbers(cube(), "5,5")
    with pytest.raises(ValueError, match="method"):
        zdg.thinning(cube(), method="magic")
    with pytest.raises(ValueError, match="phase"):
        zdg.connected_components(cube(), 26, phase="neither")


def test_simple_points_of_a_square_and_a_ring():
    """In a filled 3 x 3 square (8,4) the corners and edge midpoints are simple, the centre is
    not; in a ring (a hole) no point of a 1-thick loop is simple."""
    square = np.zeros((5, 5), np.uint8)
    square[1:4, 1:4] = 1
    s = zdg.simple_points(square)
    assert s.dtype == np.uint8 and s[2, 2] == 0 and s[1, 1] == 1 and s[1, 2] == 1
    ring = square.copy()
    ring[2, 2] = 0
    assert zdg.simple_points(ring, adjacency="4,8").sum() == 0
