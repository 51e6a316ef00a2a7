#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds examples/library's two programs against an installed torus library
# with pkg-config alone, as a Makefile would, and runs them.
#   pkg_config.sh PREFIX LIBDIR OUT_DIR CC CXX [LDFLAGS]
set -euo pipefail
prefix=$1 libdir=$2 out=$3 cc=$4 cxx=$5 ldflags=${6:-}
src="$(cd "$(dirname "$0")/../../examples/library" && pwd)"
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
rm -rf "$out" && mkdir -p "$out"
cflags=$(pkg-config --cflags toroid-torus)
libs=$(pkg-config --libs toroid-torus)
echo "pkg-config toroid-torus $(pkg-config --modversion toroid-torus): $cflags | $libs"
# shellcheck disable=SC2086
"$cc" -std=c99 -pedantic-errors -Wall -Wextra -Werror $cflags "$src/torus_hits.c" -o "$out/torus_hits_c" $libs $ldflags
# shellcheck disable=SC2086
"$cxx" -std=c++20 -Wall -Wextra -Werror $cflags "$src/torus_hits.cpp" -o "$out/torus_hits" $libs $ldflags
export LD_LIBRARY_PATH="$prefix/$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
"$out/torus_hits_c"
"$out/torus_hits"
