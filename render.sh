#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds toroid and renders the bundled default scene to bagels.png.
# Extra arguments go to `toroid render` (e.g. --width 1920 --samples 16).
set -euo pipefail
cd "$(dirname "$0")"
tools/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target toroid
build/toroid render scenes/bagels.yaml -o bagels.png "$@"
