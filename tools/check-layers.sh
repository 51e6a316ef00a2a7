#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks that every folder of src/ includes only folders of its own layer or
# below (DEVELOPERS.md, "Layers"), and that the torus library
# (src/toroid/{math,roots,torus}) includes nothing but the C++ standard
# library and itself. Lists every offending #include as FILE:LINE and exits 1.
#
#   tools/check-layers.sh          check the tree
#   tools/check-layers.sh DIR      check the src/ of another checkout
set -euo pipefail
root="${1:-$(dirname "$0")/..}"
cd "$root/src"

# Lowest first. A file in one of these folders may include "toroid/X/..."
# only where X comes no later in this list. cmd/ is src/cmd, the command line.
layers=(math roots torus core io shapes render scene cmd)
# The torus library: these folders form the toroid_torus target, which must
# build with nothing but the standard library.
standalone=(math roots torus)
# The C API's header, src/toroid/torus_c.h, belongs to the torus layer; being
# C, it may include these C standard headers (and nothing else).
c_api_header=toroid/torus_c.h
c_api_std_headers=(stddef.h)

rank() {
  local i
  for i in "${!layers[@]}"; do
    [ "${layers[$i]}" = "$1" ] && { echo "$i"; return; }
  done
  echo -1
}

status=0
report() {
  echo "$1: $2" >&2
  status=1
}

while IFS= read -r file; do
  case "$file" in
    "$c_api_header") folder=torus ;;
    toroid/*) folder=$(echo "$file" | cut -d/ -f2) ;;
    cmd/*) folder=cmd ;;
    *) report "$file" "not in a layer (src/toroid/FOLDER/ or src/cmd/)"; continue ;;
  esac
  own=$(rank "$folder")
  if [ "$own" -lt 0 ]; then
    report "$file" "folder '$folder' is not in a layer: add it to tools/check-layers.sh and DEVELOPERS.md"
    continue
  fi
  is_standalone=0
  for s in "${standalone[@]}"; do [ "$s" = "$folder" ] && is_standalone=1; done

  while IFS=: read -r line text; do
    if [ "$file" = "$c_api_header" ]; then
      if [[ ! "$text" =~ \#[[:space:]]*include[[:space:]]*\<([^\>]+)\> ]] ||
        [[ ! " ${c_api_std_headers[*]} " == *" ${BASH_REMATCH[1]} "* ]]; then
        report "$file:$line" "the C API header includes a header other than ${c_api_std_headers[*]}: $text"
      fi
    elif [[ "$text" =~ \#[[:space:]]*include[[:space:]]*\"$c_api_header\" ]]; then
      if [ "$(rank torus)" -gt "$own" ]; then
        report "$file:$line" "$folder/ includes $c_api_header, a higher layer: $text"
      fi
    elif [[ "$text" =~ \#[[:space:]]*include[[:space:]]*\"(toroid/([a-z_]+)|cmd)/ ]]; then
      target="${BASH_REMATCH[2]:-cmd}"
      theirs=$(rank "$target")
      if [ "$theirs" -lt 0 ]; then
        report "$file:$line" "includes unknown folder toroid/$target"
      elif [ "$theirs" -gt "$own" ]; then
        report "$file:$line" "$folder/ includes $target/, a higher layer: $text"
      fi
    elif [[ "$text" =~ \#[[:space:]]*include[[:space:]]*\"([^\"]+)\" ]]; then
      # Quoted includes name toroid's own headers by their path from src/;
      # unit tests (*_test.cpp, *_test_*.h) may also use the shared test
      # helpers in tests/.
      if [[ "$file" != *_test.cpp && "$file" != *_test_*.h ]] || [[ ! -e "../tests/${BASH_REMATCH[1]}" ]]; then
        report "$file:$line" "quoted include outside toroid/: $text"
      fi
    elif [ "$is_standalone" = 1 ] && [[ "$file" != *_test.cpp && "$file" != *_test_*.h ]] && [[ "$text" =~ \#[[:space:]]*include[[:space:]]*\<([^\>]+)\> ]]; then
      header="${BASH_REMATCH[1]}"
      # Standard C++ headers have no extension and no folder.
      if [[ "$header" == */* || "$header" == *.* ]]; then
        report "$file:$line" "the torus library ($folder/) includes a non-standard header: $text"
      fi
    fi
  done < <(grep -n '^[[:space:]]*#[[:space:]]*include' "$file" || true)
done < <(find toroid cmd -type f \( -name '*.h' -o -name '*.cpp' \) | sort)

if [ "$status" = 0 ]; then
  echo "layers: ok (${layers[*]})"
fi
exit "$status"
