#!/usr/bin/env bash
# Installs what is missing, builds, and runs lmgc-solve on the default case shipped in
# reference_cases/ (a copy is made under build/ so the shipped case is never written to).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
# Only what it runs: the product build of lmgc-solve (no tests, no benchmarks).
cmake --preset product >/dev/null
cmake --build --preset product --target lmgc-solve
case_dir=build/run/disk_bounce_rst
rm -rf "$case_dir" && mkdir -p "$case_dir" && cp -r reference_cases/disk_bounce_rst/DATBOX "$case_dir/"
build/product/tools/lmgc-solve "$case_dir"
echo "outputs written to $case_dir/OUTBOX/ (state files, run_report.csv) and $case_dir/POSTPRO/"
