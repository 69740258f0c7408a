#!/usr/bin/env bash
# The FCLIB benchmark (../shared/fc3d): every FC3D and FC2D problem solved by lmgc-fc3d, once with
# Gauss–Seidel sweeps only and once with the default NLGS + semismooth Newton switch, to 1e-8 in the
# natural-map error / |q|. Tables go to bench/results/<machine>/fc3d_*.txt and .csv.
# Usage: bench/fc3d_bench.sh [MAX_SECONDS_PER_PROBLEM]   (default 30)
set -euo pipefail
cd "$(dirname "$0")/.."
max_seconds="${1:-30}"
problems="${LMGC_SHARED_DIR:-../shared}/fc3d/problems"
out=bench/results/debian12-2core
tool=build/release/tools/lmgc-fc3d
[ -d "$problems" ] || { echo "fc3d_bench: no problems at $problems" >&2; exit 1; }
cmake --build --preset release --target lmgc-fc3d >/dev/null
mkdir -p "$out"
for method in nlgs nlgs+newton; do
  name="fc3d_${method/+/_}"
  "$tool" --method "$method" --max-seconds "$max_seconds" --csv "$out/$name.csv" \
    "$problems"/fc3d/*.hdf5 "$problems"/fc2d/*.hdf5 | tee "$out/$name.txt" || true
done
