#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds Debian's own oneTBB (the source package of the installed libtbb-dev,
# same version, Debian patches applied) with ThreadSanitizer, libtbb only,
# into a prefix (default build-ci-tbb-tsan/prefix) for tools/test-tsan.sh.
#
# Why: Debian's libtbb is not instrumented, so TSan cannot see the
# synchronisation inside it and reports every hand-over of work between the
# main thread and TBB's workers. With an instrumented libtbb those reports
# go away and what is left is real.
#
# The source comes through apt itself (authenticated by the Release files and
# the Debian archive keyring), with private apt directories: no root, no
# change to the machine's apt configuration. Nothing is rebuilt when the
# prefix already holds the same version.
#
# Usage: tools/build-tbb-tsan.sh [PREFIX]   (CXX picks the compiler: clang++
# by default; it must be the compiler that builds toroid with TSan.)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
work=$root/build-ci-tbb-tsan
prefix=${1:-$work/prefix}
export CXX=${CXX:-clang++}
export CC=${CC:-clang}

version=$(dpkg-query -W -f='${source:Version}' libtbb-dev)
stamp="$prefix/.toroid-tbb-tsan-$version-$(basename "$CXX")"
if [ -f "$stamp" ]; then
  echo "toroid: TSan oneTBB $version already in $prefix"
  exit 0
fi

apt_dir=$work/apt
rm -rf "$apt_dir" "$work/src" "$work/build"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$work/src"
key=/usr/share/keyrings/debian-archive-keyring.gpg
{
  echo "deb-src [signed-by=$key] http://deb.debian.org/debian bookworm main"
  echo "deb-src [signed-by=$key] http://deb.debian.org/debian bookworm-updates main"
  echo "deb-src [signed-by=$key] http://deb.debian.org/debian-security bookworm-security main"
} >"$apt_dir/sources.list"
apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o Dir::Etc::SourceParts=/nonexistent
  -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache"
  -o Debug::NoLocking=1 -o "APT::Sandbox::User=$(id -un)")
apt-get "${apt_opts[@]}" -qq update
(cd "$work/src" && apt-get "${apt_opts[@]}" -qq source "onetbb=$version" >/dev/null)
src=$(find "$work/src" -mindepth 1 -maxdepth 1 -type d -name 'onetbb-*' | head -n 1)

# libtbb only: no tests, no tbbmalloc, no tbbbind (hwloc).
cmake -S "$src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DTBB_SANITIZE=thread -DTBB_TEST=OFF \
  -DTBB_EXAMPLES=OFF -DTBBMALLOC_BUILD=OFF -DTBB_DISABLE_HWLOC_AUTOMATIC_SEARCH=ON \
  -DTBB_STRICT=OFF >/dev/null
cmake --build "$work/build" -j "$(nproc)"
cmake --install "$work/build" >/dev/null
touch "$stamp"
echo "toroid: TSan oneTBB $version installed in $prefix"
