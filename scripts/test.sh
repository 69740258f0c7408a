#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (all labels but `long`):
# first the optimised build, then the ASan+UBSan build.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release
if [ "${LMGC_SKIP_SANITIZE:-0}" != "1" ]; then
  cmake --preset sanitize >/dev/null
  cmake --build --preset sanitize
  ctest --preset sanitize
fi
