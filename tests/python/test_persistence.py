"""zdg topology persistence against GUDHI, number for number (issue #39 item 5): on random 2D and
3D volumes of several dtypes (ties, negative and fractional values), the diagrams of
`zdg topology persistence IN --json` equal those of
gudhi.CubicalComplex(top_dimensional_cells=a).persistence() (zero-length pairs dropped by both,
death None for an essential class); with --filtration dt, GUDHI runs on the signed squared
Euclidean distance computed here by brute force. GUDHI is a test package (python3-gudhi,
scripts/install-deps.sh with ZDG_TEST_PACKAGES=1): without it the file skips itself, as the other
test packages' tests do. Skipped when the CLI was not built (ctest passes its path in ZDG_CLI)."""
import json
import os
import subprocess

import numpy as np
import pytest

gudhi = pytest.importorskip("gudhi", reason="python3-gudhi (a test package) is not installed")

CLI = os.environ.get("ZDG_CLI", "")
pytestmark = pytest.mark.skipif(not CLI or not os.path.exists(CLI), reason="zdg CLI not built")


def key(p):
    return (p[0], float("inf") if p[1] is None else p[1])


def zdg_diagrams(path, *options):
    r = subprocess.run([CLI, "topology", "persistence", path, "--json", *options],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return [sorted(((float(b), None if d is None else float(d)) for b, d in g), key=key)
            for g in json.loads(r.stdout)["diagrams"]]


def gudhi_diagrams(a):
    cc = gudhi.CubicalComplex(top_dimensional_cells=np.asarray(a, dtype=np.float64))
    cc.persistence()
    return [sorted(((float(b), None if np.isinf(d) else float(d))
                    for b, d in cc.persistence_intervals_in_dimension(k)), key=key)
            for k in range(a.ndim)]


def random_volume(rng, t):
    dim = 2 + t % 2
    shape = tuple(int(s) for s in rng.integers(1, 10 if dim == 3 else 24, size=dim))
    kind = t % 4
    if kind == 0:
        return rng.integers(0, 6, size=shape).astype(np.uint8)  # many ties
    if kind == 1:
        return rng.normal(size=shape).astype(np.float64)
    if kind == 2:
        return rng.integers(-40, 40, size=shape).astype(np.int16)
    return (rng.integers(0, 20, size=shape) / 4).astype(np.float32)  # exact quarters


def test_values_filtration_equals_gudhi(tmp_path):
    rng = np.random.default_rng(39)
    for t in range(40):
        a = random_volume(rng, t)
        path = str(tmp_path / f"v{t}.npy")
        np.save(path, a)
        assert zdg_diagrams(path) == gudhi_diagrams(a), (t, a.shape, a.dtype)


def signed_squared_distance(mask):
    """-d^2 to the nearest background point on the object, +d^2 to the nearest object point on
    the background: every pair of points, for small volumes."""
    pts = np.indices(mask.shape).reshape(mask.ndim, -1).T
    flat = mask.reshape(-1) != 0
    d2 = ((pts[:, None, :] - pts[None, :, :]) ** 2).sum(axis=2)
    out = np.empty(len(pts), dtype=np.int64)
    out[flat] = -d2[np.ix_(flat, ~flat)].min(axis=1)
    out[~flat] = d2[np.ix_(~flat, flat)].min(axis=1)
    return out.reshape(mask.shape)


def test_dt_filtration_equals_gudhi_on_the_signed_distance(tmp_path):
    rng = np.random.default_rng(5)
    done = 0
    for t in range(40):
        dim = 2 + t % 2
        shape = tuple(int(s) for s in rng.integers(2, 8 if dim == 3 else 16, size=dim))
        mask = (rng.random(shape) < rng.uniform(0.2, 0.8)).astype(np.uint8)
        if mask.all() or not mask.any():
            continue
        path = str(tmp_path / f"m{t}.npy")
        np.save(path, mask)
        assert zdg_diagrams(path, "--filtration", "dt") == \
            gudhi_diagrams(signed_squared_distance(mask)), (t, shape)
        done += 1
    assert done >= 30
