#!/usr/bin/env bash
# Installs every build, test and script dependency of lmgc from Debian packages.
# Idempotent: when everything is present it returns at once without touching apt.
set -euo pipefail

packages=(
  gcc g++ cmake ninja-build ccache pkg-config
  libboost-dev libeigen3-dev libfmt-dev
  libgtest-dev libgmock-dev librapidcheck-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libhdf5-dev
  python3 python3-dev python3-numpy python3-matplotlib python3-vtk9 pybind11-dev
  clang-format
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install_deps: missing packages (${missing[*]}); run as root or install them" >&2
  exit 1
fi

echo "install_deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
