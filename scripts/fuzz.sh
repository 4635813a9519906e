#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (clang-14, ASan + UBSan, no recovery) and runs each
# for SECONDS seconds; fails on any crash, leak, sanitizer report, uncaught exception, or an
# input that takes more than 1 s or 256 MB. Prints the executions per target.
#
#   scripts/fuzz.sh [SECONDS] [NAME...]     (default 20 s; NAME: number, npy, pgm, ...)
#
# Each target first replays its seeds (tests/fuzz/corpus/NAME/) and the kept crashers
# (tests/fuzz/regressions/NAME/, each a fixed bug), then mutates from a working corpus in
# build-fuzz/corpus/NAME (new inputs do not touch the repository). A finding is saved as
# build-fuzz/artifacts/NAME-crash-... (or -leak-, -timeout-, -oom-): fix the bug, then keep the
# file in tests/fuzz/regressions/NAME/ (and as a Regression test of the parser).
# Environment: ZDG_FUZZ_BUILD (build folder, default build-fuzz), CXX (default clang++-14),
# ZDG_FUZZ_JOBS (parallel build jobs, default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
shift || true
build=${ZDG_FUZZ_BUILD:-build-fuzz}
cxx=${CXX:-clang++-14}
jobs=${ZDG_FUZZ_JOBS:-2}

if ! command -v "$cxx" >/dev/null; then
  echo "fuzz.sh: $cxx not found (Debian: apt-get install clang-14 libclang-rt-14-dev)" >&2
  exit 2
fi
# shellcheck source=scripts/ccache-env.sh
. scripts/ccache-env.sh
launcher=("${ZDG_LAUNCHER[@]}")
start=$(date +%s)
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" -DZDG_FUZZ=ON -DZDG_BUILD_TESTS=OFF -DZDG_BUILD_CLI=OFF \
  -DZDG_BUILD_BENCH=OFF -DZDG_INSTALL=OFF -DZDG_CHECK_HEADERS=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j"$jobs" --target zdg_fuzz_targets
echo "fuzz.sh: built in $(( $(date +%s) - start )) s"

names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for f in tests/fuzz/*_fuzz.cpp; do
    n=$(basename "$f" _fuzz.cpp)
    names+=("$n")
  done
fi

# One input may allocate at most 256 MB (-malloc_limit_mb). The whole process may reach 1 GB:
# ASan keeps freed memory in quarantine and its allocator metadata grows with the executions,
# which put the RSS of parsers whose live heap was 25 MB past 256 MB after a few hundred
# thousand inputs (false out-of-memory reports); the quarantine is kept small as well.
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:handle_abort=1:quarantine_size_mb=64
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
mkdir -p "$build/artifacts" "$build/logs"

# One target: replay seeds and regressions, then fuzz; the exit status goes to logs/NAME.rc.
run_one() {
  local n=$1 exe="$build/fuzz/${1}_fuzz" work="$build/corpus/$1"
  if [ ! -x "$exe" ]; then
    echo "no target $exe" >"$build/logs/$n.log"
    echo 127 >"$build/logs/$n.rc"
    return
  fi
  mkdir -p "$work"
  local dirs=("$work")
  [ -d "tests/fuzz/corpus/$n" ] && dirs+=("tests/fuzz/corpus/$n")
  [ -d "tests/fuzz/regressions/$n" ] && dirs+=("tests/fuzz/regressions/$n")
  set +e
  "$exe" -max_total_time="$seconds" -timeout=1 -rss_limit_mb=1024 -malloc_limit_mb=256 \
    -max_len=4096 -print_final_stats=1 -artifact_prefix="$build/artifacts/$n-" \
    "${dirs[@]}" >"$build/logs/$n.log" 2>&1
  echo $? >"$build/logs/$n.rc"
  set -e
}

# The targets run side by side, ZDG_FUZZ_PARALLEL at a time (default: the number of cores).
parallel=${ZDG_FUZZ_PARALLEL:-$(nproc 2>/dev/null || echo 2)}
for n in "${names[@]}"; do
  rm -f "$build/logs/$n.rc"
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
  run_one "$n" &
done
wait

failed=()
summary=()
for n in "${names[@]}"; do
  log="$build/logs/$n.log"
  rc=$(cat "$build/logs/$n.rc" 2>/dev/null || echo 1)
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  if [ "$rc" -ne 0 ]; then
    failed+=("$n")
    summary+=("$(printf '%-16s %12s executions  FAILED (exit %d, log %s)' "$n" "${execs:-?}" "$rc" "$log")")
    echo "---- $n: the end of $log" >&2
    tail -n 30 "$log" >&2
  else
    summary+=("$(printf '%-16s %12s executions  ok' "$n" "${execs:-?}")")
  fi
done

echo "fuzz.sh: ${seconds} s per target, ${parallel} at a time"
printf '%s\n' "${summary[@]}"
echo "fuzz.sh: finished in $(( $(date +%s) - start )) s"
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz.sh: FAILED: ${failed[*]} (artifacts in $build/artifacts)" >&2
  exit 1
fi
