#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian 12 packages toroid needs, only those that are missing.
#   tools/install-deps.sh [--tests] [PACKAGE...]
# --tests adds what the whole test suite needs beyond the renderer's build:
# the Python module's, the Embree adapter's and Open MPI's packages (the MPI
# render tests), and clang (the consumer test that links the GCC-built
# archive with clang).
set -euo pipefail
packages=(cmake ninja-build g++ pkg-config ccache
  libgtest-dev libgmock-dev libbenchmark-dev libyaml-cpp-dev libpng-dev libcli11-dev
  libtbb-dev libtinyobjloader-dev libopenexr-dev libmpfr-dev libgmp-dev)
for arg in "$@"; do
  if [ "$arg" = --tests ]; then
    packages+=(python3-dev python3-numpy python3-pybind11 pybind11-dev libembree-dev libopenmpi-dev openmpi-bin clang)
  else
    packages+=("$arg")
  fi
done
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "toroid: installing missing Debian packages: ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
