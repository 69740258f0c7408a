#!/bin/bash
# Runs cases through their own command.py (lmgc-run) with lmgc built under ASan + UBSan: the Python
# module is built with the sanitizers (LMGC_SANITIZE_PYTHON) and loaded into the system's Python with
# their runtimes preloaded. The sanitize preset's ctest covers the C++ alone, as its build has no
# Python module.
#
# Usage: scripts/sanitize_scripts.sh [--build-dir DIR] [--timeout SECONDS] [CASE_DIR...]
#   Without CASE_DIRs: every reference_cases/mailx_* and, when ../shared is there, LMGC90's 2D
#   deformable examples. Each case runs in a copy under DIR/sanitized-runs/. A case stopped by the
#   timeout counts as run so far (the sanitizers report as they go). Exit 1 when a run failed or a
#   sanitizer reported; the table lists every case.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD="$ROOT/build/sanitize-python"
TIMEOUT=900
CASES=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) BUILD=$2; shift 2 ;;
    --timeout) TIMEOUT=$2; shift 2 ;;
    *) CASES+=("$1"); shift ;;
  esac
done
cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DLMGC_SANITIZE=ON -DLMGC_SANITIZE_PYTHON=ON \
  -DLMGC_BUILD_TESTS=OFF -DLMGC_BUILD_BENCH=OFF >/dev/null
cmake --build "$BUILD" -j2
if [ ${#CASES[@]} -eq 0 ]; then
  CASES=("$ROOT"/reference_cases/mailx_*)
  SHARED=${LMGC_SHARED_DIR:-$ROOT/../shared}
  for example in mecaMAILx_RIGID_2D/4cubes mecaMAILx_2D/1Q4-traction mecaMAILx_2D/braudel mecaMAILx_2D/mur \
                 mecaMAILx_2D/taylor; do
    [ -d "$SHARED/lmgc90-examples/$example" ] && CASES+=("$SHARED/lmgc90-examples/$example")
  done
fi
export LD_PRELOAD="$(gcc -print-file-name=libasan.so) $(gcc -print-file-name=libubsan.so)"
export ASAN_OPTIONS=detect_leaks=0  # the interpreter's own allocations are not ours
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
printf '%-32s %6s %10s %8s\n' case exit reports seconds
for source in "${CASES[@]}"; do
  name=$(basename "$source")
  run="$BUILD/sanitized-runs/$name"
  rm -rf "$run" && mkdir -p "$run"
  cp -r "$source/DATBOX" "$source/command.py" "$run/"
  start=$(date +%s)
  set +e
  (cd "$run" && timeout "$TIMEOUT" "$BUILD/tools/lmgc-run" . --quiet >run.log 2>&1)
  code=$?
  set -e
  reports=$(grep -c "ERROR: AddressSanitizer\|runtime error" "$run/run.log" || true)
  outcome=$code
  [ "$code" -eq 124 ] && outcome=timeout
  printf '%-32s %6s %10s %8s\n' "$name" "$outcome" "$reports" "$(($(date +%s) - start))"
  if [ "$reports" -ne 0 ] || { [ "$code" -ne 0 ] && [ "$code" -ne 124 ]; }; then status=1; fi
done
exit $status
