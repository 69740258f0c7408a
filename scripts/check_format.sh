#!/usr/bin/env bash
# Fails when a tracked C++ file is not formatted as .clang-format says (clang-format from Debian).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null; then
  echo "check_format: clang-format not installed (scripts/install_deps.sh installs it)" >&2
  exit 1
fi
git ls-files '*.cpp' '*.hpp' | xargs clang-format --dry-run --Werror
echo "check_format: every tracked C++ file is formatted"
