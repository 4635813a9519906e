"""The example scripts of python/examples run and report agreement (the quick ones only; the
convergence figure takes seconds and is run by hand, see its docstring)."""
import os
import subprocess
import sys

import pytest

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "python", "examples")


def test_dt_vs_scipy_on_a_scikit_image_sample():
    pytest.importorskip("skimage")
    pytest.importorskip("scipy")
    out = subprocess.run([sys.executable, os.path.join(EXAMPLES, "dt_vs_scipy.py")], check=True,
                         capture_output=True, text=True, env=dict(os.environ)).stdout
    assert "equal after squaring and rounding: True" in out
