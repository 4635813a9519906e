"""`cmake --install build --prefix P` puts an importable package in
P/<ZDG_PYTHON_INSTALL_DIR>, the folder python/install_dir.py derives from the interpreter's
sysconfig. Skipped outside ctest (which passes the cmake program and the build folder)."""
import os
import subprocess
import sys
import sysconfig

import pytest

CMAKE = os.environ.get("ZDG_CMAKE", "")
BUILD = os.environ.get("ZDG_BUILD_DIR", "")
SITE = os.environ.get("ZDG_PYTHON_INSTALL_DIR", "")
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import install_dir  # noqa: E402


@pytest.mark.skipif(not CMAKE or not BUILD or not SITE, reason="run by ctest")
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


def test_install_dir_is_on_the_interpreters_path_for_its_own_prefixes():
    # For the interpreter's own prefixes (Debian: /usr and /usr/local) the folder chosen is one
    # the interpreter searches without PYTHONPATH.
    searched = {os.path.normpath(p) for p in sys.path}
    for prefix in {sys.prefix, "/usr/local" if "posix_local" in sysconfig.get_scheme_names() else sys.prefix}:
        path = os.path.normpath(os.path.join(prefix, install_dir.install_dir(prefix)))
        assert path in searched, (prefix, path, sorted(searched))


def test_install_dir_of_another_prefix_follows_posix_prefix(tmp_path):
    rel = install_dir.install_dir(str(tmp_path))
    expected = sysconfig.get_path("platlib", "posix_prefix",
                                  vars={"base": str(tmp_path), "platbase": str(tmp_path)})
    assert os.path.normpath(os.path.join(str(tmp_path), rel)) == os.path.normpath(expected)
