#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs a demonstration of the exact
# arithmetic core (continued fractions, Christoffel words, floor sums past 64 bits).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
zdg=build/bin/zdg
echo "== continued fraction of 415/93"
$zdg cf 415/93
echo "== Christoffel word of slope 4/7, standard factorization"
$zdg christoffel 4/7
echo "== floor sum past 64 bits (exact by escalation)"
$zdg floor-sum 1000000000000 7 123456789123 -5 --json
