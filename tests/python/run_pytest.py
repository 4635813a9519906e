"""Runs the Python module's test suite (ctest: python.pytest). Exit 77 (ctest: skipped) when
pytest or numpy is missing; the module itself must import (the build made it)."""
import sys

try:
    import numpy  # noqa: F401
    import pytest
except ImportError as e:
    print(f"zdg python tests skipped: {e}")
    sys.exit(77)

sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", *sys.argv[1:]]))
