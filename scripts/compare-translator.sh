#!/usr/bin/env bash
# Compares two wash binaries on every scene: `--dump-model` must be
# byte-identical, and the generated projects (serial, OpenMP, MPI) identical
# except for the text of the comments that replace registrations
# (`(void)0 /* ... */`, which may hold newlines) and each wash's build
# directory (the generated CMakeLists finds the runtimes there). For
# translator refactors.
#
# usage: scripts/compare-translator.sh BASE_WASH NEW_WASH [SCENE.cpp...]
set -euo pipefail
cd "$(dirname "$0")/.."
base=$1 new=$2
shift 2
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(examples/*/*.cpp test/e2e/scenes/*.cpp test/stability/closed_box.cpp)
# Every backend of backends/backends.def.
backends=$(sed -n 's/^WASH_BACKEND([^,]*, *\([a-z0-9_]*\),.*/\1/p' backends/backends.def)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# A registration comment becomes `(void)0 /**/` followed by as many newlines as
# it and the newlines right after it held, wherever it put them.
normalise() { # FILE BUILD_DIR
  BUILD="$2" perl -0pe 's{\(void\)0 /\*(.*?)\*/(\n*)}{"(void)0 /**/" . ("\n" x (($1 =~ tr/\n//) + length $2))}gse;
                        s{\Q$ENV{BUILD}\E}{<build>}g' "$1"
}
build_dir() { dirname "$(dirname "$(realpath "$1")")"; }

status=0
for scene in "${scenes[@]}"; do
  if ! diff <("$base" --dump-model "$scene" 2>&1) <("$new" --dump-model "$scene" 2>&1) >"$tmp/diff"; then
    echo "DIFF dump $scene"; head -20 "$tmp/diff"; status=1
  fi
  for backend in $backends; do
    for side in base new; do
      rm -rf "$tmp/$side"
      wash=$base; [ $side = new ] && wash=$new
      rc=0; "$wash" --backend=$backend "$scene" -o "$tmp/$side" >/dev/null 2>&1 || rc=$?
      echo $rc >"$tmp/$side.rc"
    done
    if ! cmp -s "$tmp/base.rc" "$tmp/new.rc"; then
      echo "DIFF $backend $scene: exit $(cat "$tmp/base.rc") vs $(cat "$tmp/new.rc")"; status=1
    fi
    for f in $(cd "$tmp/base" 2>/dev/null && find . -type f | sort); do
      if ! diff <(normalise "$tmp/base/$f" "$(build_dir "$base")") \
        <(normalise "$tmp/new/$f" "$(build_dir "$new")") >"$tmp/diff" 2>&1; then
        echo "DIFF $backend $scene $f"; head -20 "$tmp/diff"; status=1
      fi
    done
    if [ "$(cd "$tmp/base" 2>/dev/null && find . -type f | sort)" != "$(cd "$tmp/new" 2>/dev/null && find . -type f | sort)" ]; then
      echo "DIFF $backend $scene: different files"; status=1
    fi
  done
  echo "compared $scene"
done
exit $status
