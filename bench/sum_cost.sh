#!/usr/bin/env bash
# sum_cost.sh - the per-particle cost of the exact Sum against the ordered sum
# it replaced, side by side in one run (bench/sum/sum_cost.cpp), at each
# OpenMP thread count given.
#
# usage: bench/sum_cost.sh BUILD_DIR [N [ROUNDS [THREADS...]]]
#   defaults: N = 1048576 values, ROUNDS = 7, THREADS = 1 2
# Nothing is asserted: speed is measured, never tested.
set -euo pipefail
build=${1:?usage: bench/sum_cost.sh BUILD_DIR [N [ROUNDS [THREADS...]]]}
n=${2:-1048576} rounds=${3:-7}
shift $(( $# < 3 ? $# : 3 ))
threads=("$@")
[ ${#threads[@]} -gt 0 ] || threads=(1 2)
program=$build/bin/wash_bench_sum_cost
[ -x "$program" ] || { echo "sum_cost.sh: build $program first (ninja -C $build wash_bench_sum_cost)" >&2; exit 2; }
for t in "${threads[@]}"; do
  OMP_NUM_THREADS=$t "$program" "$n" "$rounds"
  echo
done
