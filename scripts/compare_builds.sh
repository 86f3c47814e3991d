#!/usr/bin/env bash
# Compares two wash builds scene by scene: the translator's --dump-model, and
# the final --dump of every program both builds have (reference, each backend
# of backends.def at 1, 2 and 4 threads, a distributed one at 1-4 processes),
# byte for byte. For refactorings
# that must not change what any program computes.
#   bash scripts/compare_builds.sh <old build dir> <new build dir> [steps]
set -uo pipefail
old=$1 new=$2 steps=${3:-50}
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0 compared=0
differ() { echo "DIFFERS: $*"; failures=$((failures + 1)); }

for scene in "$src"/examples/*/*.cpp "$src"/test/e2e/scenes/*.cpp "$src"/test/stability/closed_box.cpp; do
  name=$(basename "$scene" .cpp)
  "$old/bin/wash" --dump-model "$scene" >"$work/old.model" 2>"$work/old.err"
  a=$?
  "$new/bin/wash" --dump-model "$scene" >"$work/new.model" 2>"$work/new.err"
  b=$?
  compared=$((compared + 1))
  if [ $a != $b ] || ! cmp -s "$work/old.model" "$work/new.model" || ! cmp -s "$work/old.err" "$work/new.err"; then
    differ "--dump-model $name"
  fi
done

run() { # dir program args...
  local dir=$1; shift
  (cd "$work" && timeout 300 "$@" --steps "$steps" --quiet --dump "$dir.csv" --out "$dir" >/dev/null 2>&1)
}
# backends/backends.def: every backend, and whether it runs as several processes.
declare -A distributed=()
while read -r backend flag; do distributed[$backend]=$flag; done < <(
  sed -n 's/^WASH_BACKEND([^,]*, *\([a-z0-9_]*\), *"[^"]*", *\([01]\)).*/\1 \2/p' "$src/backends/backends.def")
for program in "$new"/bin/*-reference $(for b in "${!distributed[@]}"; do echo "$new/bin/*-$b"; done); do
  name=$(basename "$program")
  [ -x "$old/bin/$name" ] || continue
  case "$name" in blowup-*|misuse-*|support_errors-*|variable_unadded-*|ca_fluid_sim_*) continue ;; esac
  backend=${name##*-}
  case "$backend" in
    reference|serial) counts="1" ;; # the serial program starts no threads
    *) [ "${distributed[$backend]:-0}" = 1 ] && counts="1 2 3 4" || counts="1 2 4" ;;
  esac
  for n in $counts; do
    if [ "${distributed[$backend]:-0}" = 1 ]; then
      launch=(mpirun --allow-run-as-root --oversubscribe -np "$n")
      export OMP_NUM_THREADS=1
    else
      launch=()
      export OMP_NUM_THREADS=$n
    fi
    run old "${launch[@]}" "$old/bin/$name"; a=$?
    run new "${launch[@]}" "$program"; b=$?
    compared=$((compared + 1))
    if [ $a != 0 ] || [ $b != 0 ] || ! cmp -s "$work/old.csv" "$work/new.csv"; then
      differ "$name at $n (exit $a/$b)"
    fi
    rm -rf "$work/old" "$work/new" "$work/old.csv" "$work/new.csv"
  done
done
echo "compare_builds: $compared compared, $failures differ"
[ $failures = 0 ]
