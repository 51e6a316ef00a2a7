#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds toroid and runs every test (ctest). Installs missing Debian packages first.
set -euo pipefail
cd "$(dirname "$0")"
tools/install-deps.sh --tests
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTOROID_PYTHON=ON -DTOROID_EMBREE=ON -DTOROID_MPI=ON >/dev/null
cmake --build build
ctest --test-dir build --output-on-failure -j "$(nproc)"
