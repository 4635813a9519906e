"""The module and the command line compute the same things: the transform and the Betti
numbers of the same file agree, and a bad input gets the same one-line message (the CLI's
`zdg: MESSAGE` on stderr, the module's exception text). Skipped when the CLI was not built
(ctest passes its path in ZDG_CLI)."""
import json
import os
import subprocess

import numpy as np
import pytest

import zdg

CLI = os.environ.get("ZDG_CLI", "")
pytestmark = pytest.mark.skipif(not CLI or not os.path.exists(CLI), reason="zdg CLI not built")


def run(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


def test_distance_transform_and_betti_numbers_agree(tmp_path):
    rng = np.random.default_rng(16)
    image = (rng.random((12, 13, 14)) < 0.7).astype(np.uint8)
    src = str(tmp_path / "in.npy")
    np.save(src, image)
    for metric in ("l2", "l1", "linf", "l3"):
        out = str(tmp_path / f"dt_{metric}.npy")
        r = run("transform", "dt", src, "-o", out, "--metric", metric, "--threads", "1")
        assert r.returncode == 0, r.stderr
        assert np.array_equal(np.load(out).astype(np.int64),
                              zdg.distance_transform(image, metric=metric).astype(np.int64))
    r = run("topology", "betti", src, "--json")
    assert r.returncode == 0, r.stderr
    cli = json.loads(r.stdout)
    assert [int(b) for b in cli["betti"]] == list(zdg.betti_numbers(image)["betti"])


def test_same_one_line_message(tmp_path):
    src = str(tmp_path / "full.npy")
    np.save(src, np.ones((4, 4), dtype=np.uint8))
    r = run("transform", "dt", src, "-o", str(tmp_path / "out.npy"))
    assert r.returncode == 2
    with pytest.raises(ValueError) as e:
        zdg.distance_transform(np.ones((4, 4), dtype=np.uint8))
    assert r.stderr.strip() == f"zdg: {e.value}"
