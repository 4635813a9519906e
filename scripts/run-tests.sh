#!/usr/bin/env bash
# The test suite: installs what is missing, builds (Release, warnings as errors: the same
# configuration as the main job, whose build it reuses), runs every test except those labelled
# "slow" (run them with: ctest --test-dir build -L slow). The tests' own packages (Chromium and
# Selenium for the viewer pages) are installed here too.
set -euo pipefail
cd "$(dirname "$0")/.."
ZDG_TEST_PACKAGES=1 scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build -LE slow -j"$(nproc 2>/dev/null || echo 2)" --output-on-failure --timeout 900
