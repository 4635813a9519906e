#!/usr/bin/env bash
# Configures and builds zdg in build/ (Release, warnings as errors): the targets given as
# arguments (e.g. zdg_cli), or everything the test suite needs when none is given (the library,
# the command line, the tests, the Python module; the benchmarks are the target `benchmarks`).
# The main job and the test suite configure build/ with the same flags, so that the second
# reuses what the first compiled. Uses ccache when it is installed (scripts/ccache-env.sh: paths
# relative to the clone, so a second clone hits the cache of the first).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
# shellcheck source=scripts/ccache-env.sh
. scripts/ccache-env.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DZDG_WERROR=ON "${ZDG_LAUNCHER[@]}" \
  ${ZDG_CMAKE_ARGS:-} >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$jobs" "${targets[@]}"
