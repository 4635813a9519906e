"""`cmake --install build --prefix P` puts an importable package in
P/<ZDG_PYTHON_INSTALL_DIR> (P/lib/python3/dist-packages by default). Skipped outside ctest
(which passes the cmake program and the build folder)."""
import os
import subprocess
import sys

import pytest

CMAKE = os.environ.get("ZDG_CMAKE", "")
BUILD = os.environ.get("ZDG_BUILD_DIR", "")
SITE = os.environ.get("ZDG_PYTHON_INSTALL_DIR", "lib/python3/dist-packages")


@pytest.mark.skipif(not CMAKE or not BUILD, reason="run by ctest")
def test_installed_package_imports(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run([CMAKE, "--install", BUILD, "--prefix", str(prefix)], check=True,
                   capture_output=True)
    site = prefix / SITE
    assert (site / "zdg" / "__init__.pyi").exists() and (site / "zdg" / "py.typed").exists()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    out = subprocess.run([sys.executable, "-c", "import zdg; print(zdg.__file__); "
                          "print(zdg.cf(2**200, 3)['integer_type'])"],
                         check=True, capture_output=True, text=True, env=env, cwd=tmp_path).stdout
    assert out.splitlines() == [str(site / "zdg" / "__init__.py"), "bigint"]
