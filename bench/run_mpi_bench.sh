#!/usr/bin/env bash
# run_mpi_bench.sh - the MPI program against the OpenMP program on the same cores.
#
# For each size, runs the seed scene scaled to N particles (bench/scenes):
#   ca_fluid_sim_N-openmp with 1 and 2 threads, and
#   ca_fluid_sim_N-mpi with 1, 2 and 4 ranks of 1 thread each (4 ranks on this
#   2-core machine are oversubscribed),
# and prints ns per particle-step, the ratio to OpenMP with the same number of
# cores (2 ranks vs 2 threads), and the halo and migration bytes per step the
# MPI program reports. Measured, not asserted.
#
# ns per particle-step is the program's own clock of its steps ("steps alone"
# in its summary line): start-up (MPI_Init, the init kernels, which every rank
# runs, the initial share) and the final output are not in it. They take
# seconds at 1M particles and vary by seconds on a shared machine, which made
# the earlier wall-clock difference (S steps minus 0 steps) too noisy to compare
# the programs with.
#
# With --repeat R, each size is measured R times in rounds that visit every
# program once (so drift of a shared machine hits them alike), and each
# program's fastest run is kept.
#
# usage: bench/run_mpi_bench.sh [--bin DIR] [--sizes "N ..."] [--steps-for N:S ...] [--repeat R]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bin=$here/../build/bin
sizes="65536 1048576"
declare -A steps_for=([65536]=100 [1048576]=10)
repeat=1
while [[ $# -gt 0 ]]; do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --steps-for) steps_for[${2%%:*}]=${2#*:}; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    *) echo "run_mpi_bench.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
[[ $repeat =~ ^[1-9][0-9]*$ ]] || { echo "run_mpi_bench.sh: --repeat expects a positive integer" >&2; exit 2; }
mpirun=(mpirun --allow-run-as-root --oversubscribe)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run_log STEPS CMD...: runs the program; its output is in $work/log.
run_log() {
  local steps=$1; shift
  "$@" --steps "$steps" --out "$work/out" >"$work/log" 2>&1 || {
    echo "run_mpi_bench.sh: '$*' failed:" >&2; tail -5 "$work/log" >&2; exit 1; }
}

# steps_ns CONFIG STEPS CMD...: the program's ns per particle-step; keeps its
# output as $work/log.CONFIG.
steps_ns() {
  local config=$1; shift
  run_log "$@"
  cp "$work/log" "$work/log.$config"
  sed -n 's/.*steps alone [0-9.]* s, \([0-9.]*\) ns per particle-step.*/\1/p' "$work/log"
}

# min A B: the smaller of two numbers ("" counts as none yet).
min() { awk -v a="$1" -v b="$2" 'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }'; }

printf '%-9s %-8s %7s %6s %11s %9s %14s %14s\n' size program cores steps ns/p-step ratio halo_B/step migr_B/step
for n in $sizes; do
  steps=${steps_for[$n]:-20}
  omp=$bin/ca_fluid_sim_$n-openmp mpi=$bin/ca_fluid_sim_$n-mpi
  configs=(omp1 omp2 mpi1 mpi2 mpi4)
  declare -A ns=()
  # measure CONFIG: ns per particle-step of one run of that program.
  measure() {
    case $1 in
      omp*) OMP_NUM_THREADS=${1#omp} steps_ns "$1" "$steps" "$omp" ;;
      mpi*) OMP_NUM_THREADS=1 steps_ns "$1" "$steps" "${mpirun[@]}" -np "${1#mpi}" "$mpi" ;;
    esac
  }
  for ((round = 0; round < repeat; round++)); do
    for c in "${configs[@]}"; do
      ns[$c]=$(min "${ns[$c]:-}" "$(measure "$c")")
    done
  done
  for t in 1 2; do
    printf '%-9s %-8s %7s %6s %11s %9s %14s %14s\n' "$n" openmp "$t" "$steps" "${ns[omp$t]}" 1.00 - -
  done
  for r in 1 2 4; do
    halo=$(sed -n 's/.*halo exchange \([0-9]*\) bytes\/step.*/\1/p' "$work/log.mpi$r")
    migr=$(sed -n 's/.*particle migration \([0-9]*\) bytes\/step.*/\1/p' "$work/log.mpi$r")
    cores=$(( r < 2 ? r : 2 ))
    ratio=$(awk -v a="${ns[mpi$r]}" -v b="${ns[omp$cores]}" 'BEGIN { printf "%.2f", a / b }')
    printf '%-9s %-8s %7s %6s %11s %9s %14s %14s\n' "$n" "mpi-$r" "$cores" "$steps" "${ns[mpi$r]}" "$ratio" "$halo" "$migr"
  done
done
echo "(ratio: MPI ns/p-step over OpenMP's with as many threads as cores used; 4 ranks share 2 cores;"
echo " each figure from the fastest of $repeat interleaved runs)"
