#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Formats every C++ file of the tree with .clang-format (Debian's
# clang-format 14) and checks that each source file carries the licence's
# SPDX line.
#
#   tools/format.sh           format in place
#   tools/format.sh --check   change nothing; list what is unformatted or
#                             lacks the SPDX line, and exit 1 if anything is
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
[ "${1:-}" = "--check" ] && check=1

clang_format=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$clang_format" ]; then
  tools/install-deps.sh clang-format
  clang_format=$(command -v clang-format-14 || command -v clang-format)
fi

mapfile -t cxx < <(git ls-files --cached --others --exclude-standard -- '*.h' '*.cpp' '*.c' '*.cu' '*.cuh')
mapfile -t scripts < <(git ls-files --cached --others --exclude-standard -- '*.sh' '*.awk' '*.py' '*.cmake' 'CMakeLists.txt' '*/CMakeLists.txt' '.ci/run')
spdx="SPDX-License-Identifier: Apache-2.0"
status=0

for f in "${cxx[@]}" "${scripts[@]}"; do
  [ -f "$f" ] || continue
  if ! head -n 3 "$f" | grep -q "$spdx"; then
    echo "$f: no '$spdx' line in its first three lines" >&2
    status=1
  fi
done

if [ "$check" = 1 ]; then
  for f in "${cxx[@]}"; do
    [ -f "$f" ] || continue
    if ! "$clang_format" --style=file "$f" | cmp -s - "$f"; then
      echo "$f: not formatted (run tools/format.sh)" >&2
      status=1
    fi
  done
  [ "$status" = 0 ] && echo "format: ok (${#cxx[@]} C++ files, ${#scripts[@]} scripts)"
  exit "$status"
fi

"$clang_format" --style=file -i "${cxx[@]}"
exit "$status"
