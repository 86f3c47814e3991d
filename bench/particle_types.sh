#!/usr/bin/env bash
# The same 2D dam break in a tank of wall particles written with a "wall"
# flag that every kernel tests (bench/scenes/dam_break_walls_flag.cpp) and
# with particle types (dam_break_walls_typed.cpp), side by side in one run:
# the OpenMP programs at 1 and 2 threads, alternating, best of ROUNDS. Prints
# the steps' time per fluid-particle-step of each and flag/typed (above 1:
# typed is faster), and checks that both computed the same fluid.
#   bash bench/particle_types.sh BUILD_DIR [STEPS] [ROUNDS]
set -euo pipefail
build=$1 steps=${2:-200} rounds=${3:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A best
for round in $(seq "$rounds"); do
  for threads in 1 2; do
    for variant in flag typed; do
      line=$(OMP_NUM_THREADS=$threads "$build/bin/dam_break_walls_$variant-openmp" --steps "$steps" \
        --dump "$work/$variant.csv" --out "$work/out" | tail -n 1)
      alone=$(sed -E 's/.*steps alone ([0-9.]+) s.*/\1/' <<<"$line")
      key=$variant-$threads
      if [ -z "${best[$key]:-}" ] || awk -v a="$alone" -v b="${best[$key]}" 'BEGIN { exit !(a < b) }'; then
        best[$key]=$alone
      fi
    done
  done
done
# Fluid particles: the last column (the wall flag, the type) is 0.
fluid=$(awk -F, 'NR > 1 && $NF == 0' "$work/flag.csv" | wc -l)
typedFluid=$(awk -F, 'NR > 1 && $NF == 0' "$work/typed.csv" | wc -l)
[ "$fluid" = "$typedFluid" ] || { echo "fluid counts differ: $fluid and $typedFluid" >&2; exit 1; }
# The same physics: id, position, velocity and density of every particle agree.
cmp -s <(cut -d, -f1-6 "$work/flag.csv") <(cut -d, -f1-6 "$work/typed.csv") ||
  { echo "the flag and typed programs computed different states" >&2; exit 1; }
particles=$(($(wc -l < "$work/flag.csv") - 1))
echo "dam break: $particles particles, $fluid fluid, $steps steps, best of $rounds (identical states)"
for threads in 1 2; do
  f=${best[flag-$threads]} t=${best[typed-$threads]}
  awk -v f="$f" -v t="$t" -v n="$fluid" -v s="$steps" -v th="$threads" 'BEGIN {
    printf "%d thread%s: flag %.1f ns, typed %.1f ns per fluid-particle-step; flag/typed %.2f\n",
      th, th == 1 ? " " : "s", f / (n * s) * 1e9, t / (n * s) * 1e9, f / t }'
done
