#!/usr/bin/env bash
# lmgc's default method against Siconos NSGS on one FCLIB problem, as a ratio measured in one run.
# This machine's speed drifts from minute to minute by more than the difference between the two, so
# single solves do not compare: each round solves the problem ten times in one process with each
# program, back to back, and takes the median solve of each; the ratio of the two medians is the
# round's figure, and the median over the rounds is the result.
# Usage: bench/fc3d_head_to_head.sh PROBLEM.hdf5 [ROUNDS]   (default 12; needs fc3d_siconos_peer,
# built when Debian's libsiconos-numerics-dev is installed)
set -euo pipefail
cd "$(dirname "$0")/.."
problem="$1"
rounds="${2:-12}"
lmgc=build/release/tools/lmgc-fc3d
peer=build/release/bench/fc3d_siconos_peer
cmake --build --preset release --target lmgc-fc3d >/dev/null
cmake --build --preset release --target fc3d_siconos_peer >/dev/null 2>&1 ||
  { echo "fc3d_head_to_head: fc3d_siconos_peer not built (install libsiconos-numerics-dev)" >&2; exit 1; }
files=()
for _ in $(seq 10); do files+=("$problem"); done
median() { sort -g | sed -n 5p; }  # the lower median of ten
ratios=()
echo "# $(basename "$problem"): median solve of ten per program per round; ratio = lmgc / Siconos NSGS"
for round in $(seq "$rounds"); do
  l=$("$lmgc" "${files[@]}" | awk '$1 ~ /hdf5$/ {print $6}' | median)
  s=$("$peer" "${files[@]}" --solvers nsgs | awk '$1 ~ /hdf5$/ {print $6}' | median)
  r=$(awk -v l="$l" -v s="$s" 'BEGIN {printf "%.3f", l / s}')
  ratios+=("$r")
  echo "round $round  lmgc $l s  nsgs $s s  ratio $r"
done
printf '%s\n' "${ratios[@]}" | sort -g |
  awk '{v[NR] = $1} END {m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2;
       printf "median ratio %.2f over %d rounds (from %.2f to %.2f)\n", m, NR, v[1], v[NR]}'
