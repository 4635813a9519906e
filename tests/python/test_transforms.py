"""Distance transforms on numpy arrays: equal to scipy.ndimage's (squared and rounded) and to
brute force, zero-copy in and out, the GIL released."""
import threading
import time
import tracemalloc

import numpy as np
import pytest

import zdg

ndimage = pytest.importorskip("scipy.ndimage")
hyp = pytest.importorskip("hypothesis")
from hypothesis import given, settings, strategies as st  # noqa: E402
from hypothesis.extra.numpy import arrays  # noqa: E402


def brute_force(image, p, torus=()):
    """min over zero points y of sum_k |x_k - y_k|^p (max for p = 0, l_inf)."""
    shape = image.shape
    zeros = np.argwhere(image == 0)
    out = np.zeros(shape, dtype=object)
    for x in np.ndindex(*shape):
        best = None
        for y in zeros:
            diffs = []
            for k, (a, b) in enumerate(zip(x, y)):
                t = abs(int(a) - int(b))
                if torus and torus[k]:
                    t = min(t, shape[k] - t)
                diffs.append(t)
            v = max(diffs) if p == 0 else sum(t**p for t in diffs)
            best = v if best is None else min(best, v)
        out[x] = best
    return out


binary_images = st.integers(1, 3).flatmap(
    lambda d: arrays(np.bool_, st.tuples(*[st.integers(1, 7)] * d)))


@given(binary_images)
def test_l2_equals_scipy_edt_squared(image):
    """Theorem (exactness): DT_l2 = round(edt^2) where scipy's edt is exact up to rounding."""
    if image.all():
        return
    ours = zdg.distance_transform(image)
    ref = np.rint(ndimage.distance_transform_edt(image) ** 2).astype(np.int64)
    assert ours.shape == image.shape and np.array_equal(ours, ref)


@given(binary_images)
def test_l1_and_linf_equal_scipy_chamfer(image):
    """l1 is the 4-/6-... chamfer (taxicab) distance, linf the chessboard one: both exact."""
    if image.all():
        return
    assert np.array_equal(zdg.distance_transform(image, metric="l1"),
                          ndimage.distance_transform_cdt(image, metric="taxicab"))
    assert np.array_equal(zdg.distance_transform(image, metric="linf"),
                          ndimage.distance_transform_cdt(image, metric="chessboard"))


@settings(max_examples=30)  # brute force is quadratic in the image size
@given(arrays(np.uint8, st.tuples(st.integers(1, 5), st.integers(1, 5))),
       st.sampled_from([1, 2, 3, 7, 0]), st.tuples(st.booleans(), st.booleans()))
def test_lp_on_the_torus_equals_brute_force(image, p, torus):
    if image.all():
        return
    metric = "linf" if p == 0 else f"l{p}"
    ours = zdg.distance_transform(image, metric=metric, torus=torus)
    assert [int(v) for v in ours.ravel()] == list(brute_force(image, p, torus).ravel())
    # F order: the axes are reversed inside, the torus flags with them.
    f = zdg.distance_transform(np.asfortranarray(image), metric=metric, torus=torus)
    assert np.array_equal(f, ours)


@given(arrays(np.int16, st.tuples(st.integers(1, 6), st.integers(1, 6), st.integers(1, 6)),
              elements=st.integers(-3, 3)))
def test_any_dtype_and_layout_gives_the_same_result(image):
    """Nonzero = object whatever the dtype; C order, F order and strided views agree."""
    if image.all():
        return
    ref = zdg.distance_transform((image != 0).astype(np.uint8))
    assert np.array_equal(zdg.distance_transform(image), ref)
    f = zdg.distance_transform(np.asfortranarray(image != 0))
    assert f.flags["F_CONTIGUOUS"] and np.array_equal(f, ref)
    t = zdg.distance_transform((image != 0).transpose(2, 0, 1))
    assert np.array_equal(t, ref.transpose(2, 0, 1))


def test_values_beyond_64_bits_are_exact_python_ints():
    image = np.ones((1, 40), dtype=np.uint8)
    image[0, 0] = 0
    ours = zdg.distance_transform(image, metric="l200")
    assert ours.dtype == object
    assert [int(v) for v in ours[0]] == [x**200 for x in range(40)]


def test_zero_copy_input_and_output():
    """A C- or F-contiguous bool/uint8 input is not copied: the only allocation is the
    result (int32 here), and the result owns its memory."""
    image = np.ones((64, 64, 64), dtype=np.bool_)
    image[32, 32, 32] = False
    for a in (image, np.asfortranarray(image), image.view(np.uint8)):
        tracemalloc.start()
        out = zdg.distance_transform(a, threads=1)
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        assert out.dtype == np.int32
        assert peak < out.nbytes * 1.05 + 65536
        assert out.flags["OWNDATA"] and out.flags["WRITEABLE"]
        assert not np.shares_memory(out, a)


def test_the_gil_is_released():
    """While one thread is inside the transform, another runs Python code. The main thread
    samples the clock (sleeping 1 ms between samples) while the worker runs one-thread
    transforms on growing cubes until a call lasts at least 60 ms (how large that cube is
    depends on the machine). With the GIL held for the call, the main thread could run only
    before the worker enters the C++ code (at most one switch interval, 5 ms) and after it
    returns, so no sample could fall in the middle half of that call."""
    calls = []
    samples = []
    done = threading.Event()

    def work():
        try:
            n = 160
            while True:
                image = np.ones((n, n, n), dtype=np.bool_)
                image[0, 0, 0] = False
                start = time.perf_counter()
                zdg.distance_transform(image, threads=1)
                calls.append((n, start, time.perf_counter()))
                if calls[-1][2] - start >= 0.06 or n >= 640:
                    break
                n = min(640, int(n * 1.3))
        finally:
            done.set()

    t = threading.Thread(target=work)
    t.start()
    while not done.is_set():
        samples.append(time.perf_counter())
        time.sleep(0.001)
    t.join()
    n, start, end = calls[-1]
    # Meaningful only for a call long against the switch interval and the sampling step.
    assert end - start >= 0.06, f"a {n}^3 transform took only {end - start:.3f} s"
    quarter = (end - start) / 4
    inside = [x for x in samples if start + quarter < x < end - quarter]
    assert inside, f"no sample in the middle of a {end - start:.3f} s call ({n}^3)"


def test_bad_input():
    with pytest.raises(ValueError, match="no background point"):
        zdg.distance_transform(np.ones((3, 3)))
    with pytest.raises(ValueError, match="metric"):
        zdg.distance_transform(np.zeros((3, 3)), metric="l0")
    with pytest.raises(ValueError, match="torus"):
        zdg.distance_transform(np.zeros((3, 3)), torus=(True,))
    with pytest.raises(ValueError, match="0-dimensional"):
        zdg.distance_transform(np.array(1))


@given(binary_images, st.sampled_from(["l1", "l2", "linf", "l3"]))
def test_voronoi_sites_are_nearest_zero_points(image, metric):
    """The site of every point is a zero point at the distance the transform gives."""
    if image.all():
        return
    p = {"l1": 1, "l2": 2, "l3": 3, "linf": 0}[metric]
    sites = zdg.voronoi_map(image, metric=metric)
    dt = zdg.distance_transform(image, metric=metric)
    assert sites.shape == image.shape and sites.dtype == np.int64
    flat = image.ravel()
    for i, s in enumerate(sites.ravel()):
        assert not flat[s]
        x = np.unravel_index(i, image.shape)
        y = np.unravel_index(int(s), image.shape)
        d = [abs(int(a) - int(b)) for a, b in zip(x, y)]
        assert (max(d) if p == 0 else sum(t**p for t in d)) == dt.ravel()[i]


@given(binary_images, st.sampled_from(["l1", "l2", "linf"]))
def test_medial_axis_balls_rebuild_the_shape(image, metric):
    """Theorem (Coeurjolly-Montanvert 2007): the reverse transform of the reduced medial axis
    is the shape, and so is the reverse transform of the whole distance transform; the
    centres are object points with their DT value."""
    if image.all():
        return
    dt = zdg.distance_transform(image, metric=metric)
    assert np.array_equal(zdg.reverse_distance_transform(dt, metric=metric).astype(bool), image)
    centres, values = zdg.reduced_medial_axis(image, metric=metric)
    balls = np.zeros(image.shape, dtype=np.int64)
    for c, v in zip(centres, values):
        assert image[tuple(c)] and dt[tuple(c)] == v
        balls[tuple(c)] = v
    assert np.array_equal(zdg.reverse_distance_transform(balls, metric=metric).astype(bool), image)



MEMORY_CHECK = r"""
import resource, sys
import numpy as np
import zdg
n = int(sys.argv[2])
a = np.ones((n, n, n), dtype=np.uint8)
a[n // 2, n // 2, n // 2] = 0
a[0, 0, 0] = 0
def peak():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # bytes (KiB on Linux)
base = peak()
out = getattr(zdg, sys.argv[1])(a, threads=2)
grown = peak() - base
print(a.nbytes, out.nbytes, grown)
"""


@pytest.mark.parametrize("function,n,work", [("distance_transform", 512, 0),
                                             ("voronoi_map", 256, 4)])
def test_large_calls_do_not_copy_their_input(function, n, work):
    """The issue's zero-copy check at scale, in a fresh interpreter (where ru_maxrss is this
    call's peak): the 512^3 distance transform grows the resident memory by at most input +
    output + 5% (in fact by the output alone: the input is read in place and the result is
    computed in its own buffer); the Voronoi map also needs its squared distances (int32, 4
    bytes a voxel) beside the sites (int64): its growth stays below 1.05 (output + work),
    which a copy of the input (1 byte a voxel, 20% of that) would exceed."""
    import subprocess
    import sys
    r = subprocess.run([sys.executable, "-c", MEMORY_CHECK, function, str(n)],
                       capture_output=True, text=True, check=True)
    inp, out, grown = (int(v) for v in r.stdout.split())
    if work == 0:
        assert grown <= 1.05 * (inp + out), (inp, out, grown)
    assert grown <= 1.05 * (out + work * n**3) + 4 * 2**20, (inp, out, grown)


def metric_distance(x, y, shape, torus, p):
    d = []
    for k in range(len(shape)):
        t = abs(int(x[k]) - int(y[k]))
        if torus[k]:
            t = min(t, shape[k] - t)
        d.append(t)
    return max(d) if p == 0 else sum(t ** p for t in d)


def test_voronoi_map_and_medial_axis_read_fortran_order_in_place():
    """An F-ordered mask is read in place: its Voronoi sites (C-order indices of the array's
    shape) are background points attaining the distance transform, as for the C-ordered copy
    (ties may pick another site), and its medial balls rebuild the shape (reverse DT), with
    torus flags following the axes."""
    rng = np.random.default_rng(3)
    for shape, torus in (((9, 13, 7), (True, False, False)), ((17, 11), (False, True))):
        c = (rng.random(shape) < 0.9).astype(np.uint8)
        c.flat[0] = 0
        f = np.asfortranarray(c)
        assert f.flags["F_CONTIGUOUS"] and not f.flags["C_CONTIGUOUS"]
        for metric, p in (("l2", 2), ("l1", 1), ("linf", 0)):
            dt = zdg.distance_transform(c, metric=metric, torus=torus)
            for a in (c, f):
                v = zdg.voronoi_map(a, metric=metric, torus=torus)
                for x in np.ndindex(*shape):
                    y = np.unravel_index(v[x], shape)
                    assert c[y] == 0
                    assert metric_distance(x, y, shape, torus, p) == dt[x], (shape, metric, x)
                centres, values = zdg.reduced_medial_axis(a, metric=metric, torus=torus)
                weights = np.zeros(shape, dtype=np.int64)
                for ctr, val in zip(centres, values):
                    weights[tuple(ctr)] = val
                rebuilt = zdg.reverse_distance_transform(weights, metric=metric, torus=torus)
                assert np.array_equal(rebuilt, c), (shape, metric)


def test_power_map_and_reverse_dt_read_int64_weights_in_place():
    rng = np.random.default_rng(4)
    w = np.where(rng.random((40, 30)) < 0.05, rng.integers(1, 30, (40, 30)), 0)
    for dtype in (np.int64, np.int32, np.uint8):
        s, neg = zdg.power_map(w.astype(dtype))
        s64, neg64 = zdg.power_map(w.astype(np.int64))
        assert np.array_equal(s, s64) and np.array_equal(neg, neg64)
        assert np.array_equal(zdg.reverse_distance_transform(w.astype(dtype)),
                              zdg.reverse_distance_transform(w.astype(np.int64)))


POWER_MEMORY = r"""
import resource, sys
import numpy as np
import zdg
n = 256
# Written (np.full), so that its pages are resident before the baseline: np.zeros maps them
# lazily, and whether the first reads then add them to the resident size depends on the kernel
# (they did on the development VM: 134 MB, counted as if the call had copied the weights).
w = np.full((n, n, n), 0, dtype=np.int64)
w[::37, ::41, ::43] = 50
def peak():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
base = peak()
site, negative = zdg.power_map(w, threads=2)
print(w.nbytes, site.nbytes + negative.nbytes, peak() - base)
"""


def test_power_map_does_not_copy_int64_weights():
    """256^3 int64 weights (128 MB) read in place: the growth is the outputs (sites int64,
    flags uint8) and the int32 working values, 13 bytes a voxel; a copy of the weights would
    add 8 more."""
    import subprocess
    import sys
    r = subprocess.run([sys.executable, "-c", POWER_MEMORY], capture_output=True, text=True,
                       check=True)
    inp, out, grown = (int(v) for v in r.stdout.split())
    n3 = 256**3
    assert out == 9 * n3
    assert grown <= 1.05 * (out + 4 * n3) + 4 * 2**20, (inp, out, grown)


@pytest.mark.parametrize("dtype", [np.int16, np.uint16, np.int32, np.uint32, np.int64, ">i4"])
def test_integer_masks_of_any_width_are_read_in_place(dtype):
    """Integer masks of 2, 4 and 8 bytes (either byte order) give the transforms of their
    nonzero set, values whose low byte is 0 included, without a copy of the input."""
    rng = np.random.default_rng(8)
    b = rng.random((33, 21, 17)) < 0.85
    b[0, 0, 0] = False
    wide = np.where(b, 256, 0).astype(dtype)  # low byte 0: object all the same
    for order in ("C", "F"):
        a = np.asarray(wide, order=order)
        assert np.array_equal(zdg.distance_transform(a), zdg.distance_transform(b))
    v = zdg.voronoi_map(wide)
    dt = zdg.distance_transform(b)
    sites = np.unravel_index(v, b.shape)
    assert not b[sites].any()
    idx = np.indices(b.shape)
    d2 = sum((idx[k] - sites[k]) ** 2 for k in range(3))
    assert np.array_equal(d2, dt)
    tracemalloc.start()
    out = zdg.distance_transform(wide)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < out.nbytes * 1.05 + 65536  # the result only: the input is not reduced


two_or_three_d = st.integers(2, 3).flatmap(
    lambda d: arrays(np.uint8, st.tuples(*[st.integers(1, 9 if d == 2 else 5)] * d),
                     elements=st.integers(0, 1)))


@given(two_or_three_d)
def test_chamfer_unit_masks_equal_scipy_cdt(image):
    """Peer oracle: the chamfer masks <1> and <1,1> (<1,1,1> in 3D) are scipy's taxicab and
    chessboard chamfer transforms."""
    if image.all():
        return
    full = [1, 1] if image.ndim == 2 else [1, 1, 1]
    assert np.array_equal(zdg.chamfer_transform(image, mask=[1]),
                          ndimage.distance_transform_cdt(image, metric="taxicab"))
    assert np.array_equal(zdg.chamfer_transform(image, mask=full),
                          ndimage.distance_transform_cdt(image, metric="chessboard"))
    # Fortran order gives the same values (the masks are symmetric under axis permutations).
    assert np.array_equal(zdg.chamfer_transform(np.asfortranarray(image)),
                          zdg.chamfer_transform(image))


def test_chamfer_errors():
    with pytest.raises(ValueError, match="1-D array"):
        zdg.chamfer_transform(np.array([1, 0, 1], dtype=np.uint8))
    with pytest.raises(ValueError, match="positive"):
        zdg.chamfer_transform(np.array([[1, 0]], dtype=np.uint8), mask=[3, 0])


@settings(max_examples=40)  # the oracle enumerates every ball
@given(arrays(np.uint8, st.tuples(st.integers(1, 8), st.integers(1, 8)), elements=st.integers(0, 1)))
def test_local_thickness_is_the_largest_inscribed_ball(image):
    """Definition (Hildebrand, Ruegsegger 1997): at y, 2 sqrt(R2) with R2 the largest DT(c) over
    the centres c whose open ball |y - c|^2 < DT(c) (inscribed: it holds no zero point) holds y.
    Oracle: every centre's ball enumerated, DT from scipy's exact edt."""
    if image.all():
        return
    ours = zdg.local_thickness(image)
    dt = np.rint(ndimage.distance_transform_edt(image) ** 2).astype(np.int64)
    r2 = np.zeros(image.shape, dtype=np.int64)
    ys, xs = np.indices(image.shape)
    for cy, cx in zip(*np.nonzero(image)):
        inside = (ys - cy) ** 2 + (xs - cx) ** 2 < dt[cy, cx]
        r2[inside] = np.maximum(r2[inside], dt[cy, cx])
    expect = np.where(image != 0, 2 * np.sqrt(r2), 0).astype(np.float32)
    assert ours.dtype == np.float32 and ours.shape == image.shape
    assert np.array_equal(ours, expect)
    assert np.array_equal(zdg.local_thickness(np.asfortranarray(image)), ours)
