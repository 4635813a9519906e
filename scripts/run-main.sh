#!/usr/bin/env bash
# The main job: installs what is missing, builds, and reproduces (quick sweep) the 2D
# integral-invariant curvature figure of Coeurjolly, Lachaud, Levallois (CVIU 2014): the l_inf
# curvature error against h on the ellipse (20, 7) and the flower (20, 7, 6), with the fitted
# slopes checked against the proven h^{1/3} rate. Exit status 1 when a check fails.
# The results go to a new folder out/cviu2014-ii2d-<date>; nothing earlier is overwritten.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh zdg_cli   # only the program the job runs
out="out/cviu2014-ii2d-$(date +%Y%m%d-%H%M%S)"
mkdir -p out
build/bin/zdg paper cviu2014-ii2d --quick -o "$out"
echo
echo "plot: $out/convergence.png (and .svg); data: $out/results.csv, $out/summary.json"
