#!/usr/bin/env bash
# Configures and builds zdg in build/ (Release): build/bin/zdg, the tests, the benchmarks.
# Uses ccache when it is installed (scripts/ccache-env.sh: paths relative to the clone, so a
# second clone hits the cache of the first).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
# shellcheck source=scripts/ccache-env.sh
. scripts/ccache-env.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${ZDG_LAUNCHER[@]}" ${ZDG_CMAKE_ARGS:-} >/dev/null
cmake --build build -j"$jobs"
