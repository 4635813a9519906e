"""Runs the Python module's test suite (ctest: python.pytest). Exit 77 (ctest: skipped) when
pytest or numpy is missing, or when every test of the file skipped itself (e.g. the viewer
tests without a browser: the reason is printed); the module itself must import (the build
made it)."""
import sys

try:
    import numpy  # noqa: F401
    import pytest
except ImportError as e:
    print(f"zdg python tests skipped: {e}")
    sys.exit(77)


class Outcomes:
    """Counts what ran: a file whose tests all skipped is reported as skipped, not passed."""

    def __init__(self):
        self.passed = 0
        self.skipped = 0

    def pytest_runtest_logreport(self, report):
        if report.when == "call" and report.passed:
            self.passed += 1
        if report.skipped:
            self.skipped += 1

    def pytest_collectreport(self, report):
        if report.skipped:
            self.skipped += 1


outcomes = Outcomes()
code = pytest.main(["-q", "-rs", "-p", "no:cacheprovider", *sys.argv[1:]], plugins=[outcomes])
# A file that skips itself at import (pytest.skip(allow_module_level=True)) collects no test:
# pytest's exit status is then 5 (no tests collected), with the skip counted.
if code in (0, 5) and outcomes.passed == 0 and outcomes.skipped > 0:
    sys.exit(77)
sys.exit(code)
