#!/usr/bin/env bash
# run_mpi_bench.sh - the MPI program against the OpenMP program on the same cores.
#
# For each size, runs the seed scene scaled to N particles (bench/scenes):
#   ca_fluid_sim_N-openmp with 1 and 2 threads, and
#   ca_fluid_sim_N-mpi with 1, 2 and 4 ranks of 1 thread each (4 ranks on this
#   2-core machine are oversubscribed),
# and prints ns per particle-step ((wall of S steps - wall of 0 steps) / (N S)),
# the ratio to OpenMP with the same number of cores (2 ranks vs 2 threads), and
# the halo and migration bytes per step the MPI program reports. Measured, not
# asserted.
#
# usage: bench/run_mpi_bench.sh [--bin DIR] [--sizes "N ..."] [--steps-for N:S ...]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bin=$here/../build/bin
sizes="65536 1048576"
declare -A steps_for=([65536]=100 [1048576]=10)
while [[ $# -gt 0 ]]; do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --steps-for) steps_for[${2%%:*}]=${2#*:}; shift 2 ;;
    *) echo "run_mpi_bench.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
mpirun=(mpirun --allow-run-as-root --oversubscribe)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# wall_ns STEPS CMD...: wall time of one run in ns.
wall_ns() {
  local steps=$1; shift
  local t0 t1
  t0=$(date +%s%N)
  "$@" --steps "$steps" --quiet --out "$work/out" >"$work/log" 2>&1 || {
    echo "run_mpi_bench.sh: '$*' failed:" >&2; tail -5 "$work/log" >&2; exit 1; }
  t1=$(date +%s%N)
  echo $(( t1 - t0 ))
}

# per_step N STEPS CMD...: ns per particle-step.
per_step() {
  local n=$1 steps=$2; shift 2
  local full zero
  full=$(wall_ns "$steps" "$@")
  zero=$(wall_ns 0 "$@")
  awk -v a="$full" -v b="$zero" -v n="$n" -v s="$steps" 'BEGIN { printf "%.1f", (a - b) / (n * s) }'
}

printf '%-9s %-8s %7s %6s %11s %9s %14s %14s\n' size program cores steps ns/p-step ratio halo_B/step migr_B/step
for n in $sizes; do
  steps=${steps_for[$n]:-20}
  omp=$bin/ca_fluid_sim_$n-openmp mpi=$bin/ca_fluid_sim_$n-mpi
  declare -A omp_ns=()
  for t in 1 2; do
    omp_ns[$t]=$(OMP_NUM_THREADS=$t per_step "$n" "$steps" "$omp")
    printf '%-9s %-8s %7s %6s %11s %9s %14s %14s\n' "$n" openmp "$t" "$steps" "${omp_ns[$t]}" 1.00 - -
  done
  for r in 1 2 4; do
    ns=$(OMP_NUM_THREADS=1 per_step "$n" "$steps" "${mpirun[@]}" -np "$r" "$mpi")
    OMP_NUM_THREADS=1 "${mpirun[@]}" -np "$r" "$mpi" --steps "$steps" --out "$work/out" \
      >"$work/report" 2>&1
    halo=$(sed -n 's/.*halo exchange \([0-9]*\) bytes\/step.*/\1/p' "$work/report")
    migr=$(sed -n 's/.*particle migration \([0-9]*\) bytes\/step.*/\1/p' "$work/report")
    cores=$(( r < 2 ? r : 2 ))
    ratio=$(awk -v a="$ns" -v b="${omp_ns[$cores]}" 'BEGIN { printf "%.2f", a / b }')
    printf '%-9s %-8s %7s %6s %11s %9s %14s %14s\n' "$n" "mpi-$r" "$cores" "$steps" "$ns" "$ratio" "$halo" "$migr"
  done
done
echo "(ratio: MPI ns/p-step over OpenMP's with as many threads as cores used; 4 ranks share 2 cores)"
