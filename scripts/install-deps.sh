#!/usr/bin/env bash
# Installs the Debian packages cavity builds, tests and plots with, when any is missing.
# Idempotent: does nothing (and needs no network) when everything is present.
set -euo pipefail

packages=(
  cmake ninja-build g++ clang clang-format libclang-rt-14-dev
  libgmp-dev libboost-dev libcli11-dev
  libgtest-dev libbenchmark-dev libcgal-dev
  python3-matplotlib tetgen pybind11-dev python3-dev python3-numpy python3-pytest python3-scipy
  zlib1g-dev python3-meshio python3-vtk9
  python3-pip python3-setuptools python3-wheel python3-venv mypy
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

echo "install-deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
