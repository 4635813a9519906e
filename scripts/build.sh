#!/usr/bin/env bash
# Configures and builds zdg in build/ (Release): build/bin/zdg, the tests, the benchmarks.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ${ZDG_CMAKE_ARGS:-} >/dev/null
cmake --build build -j"$jobs"
