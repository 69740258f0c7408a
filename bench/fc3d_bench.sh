#!/usr/bin/env bash
# The FCLIB benchmark (../shared/fc3d): every FC3D and FC2D problem solved by lmgc-fc3d to 1e-8 in the
# natural-map error / |q|, with each method: Gauss–Seidel sweeps only (nlgs), sweeps first with a
# semismooth Newton switch (nlgs+newton), and the default, Newton phases first (newton+nlgs). Then the
# default method on the problems where sweeps stall, from five starts (0 to 4 opening sweeps): how
# often, not only whether, it solves them. Tables go to bench/results/<machine>/fc3d_*.txt and .csv.
# Usage: bench/fc3d_bench.sh [MAX_SECONDS_PER_PROBLEM]   (default 60)
set -euo pipefail
cd "$(dirname "$0")/.."
max_seconds="${1:-60}"
problems="${LMGC_SHARED_DIR:-../shared}/fc3d/problems"
out=bench/results/debian12-2core
tool=build/release/tools/lmgc-fc3d
[ -d "$problems" ] || { echo "fc3d_bench: no problems at $problems" >&2; exit 1; }
cmake --build --preset release --target lmgc-fc3d >/dev/null
mkdir -p "$out"
for method in nlgs nlgs+newton newton+nlgs; do
  name="fc3d_${method//+/_}"
  "$tool" --method "$method" --max-seconds "$max_seconds" --csv "$out/$name.csv" \
    "$problems"/fc3d/*.hdf5 "$problems"/fc2d/*.hdf5 | tee "$out/$name.txt" || true
done
hard=("$problems"/fc3d/RockPile_tob1.hdf5 "$problems"/fc3d/spheres-in-a-box-98-i10000-256-10_local.hdf5
  "$problems"/fc3d/OneObject-i100000-499.hdf5 "$problems"/fc3d/BoxesStack1-i100000-32.hdf5
  "$problems"/fc2d/*.hdf5)
{
  echo "# default method (newton+nlgs), $max_seconds s cap, from 0 to 4 opening sweeps"
  for opening in 0 1 2 3 4; do
    "$tool" --opening-sweeps "$opening" --max-seconds "$max_seconds" "${hard[@]}" |
      sed "s/^/opening $opening  /" || true
  done
} | tee "$out/fc3d_newton_nlgs_starts.txt"
