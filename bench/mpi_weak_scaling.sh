#!/bin/bash
# mpi_weak_scaling.sh: weak scaling of the MPI program, a fixed number of
# particles per rank, on P = 1, 2, 4 ranks of 1 OpenMP thread, for two scenes:
# - strip: examples/taylor_green as a row of P periodic unit squares of
#   SIDE^2 particles (`taylor_green-mpi SIDE P`; 512^2 = 262 144 a rank):
#   every rank's piece has the same shape and the same neighbours at every P,
#   so the busiest rank's bytes should stay flat as ranks are added;
# - seed: the seed scene scaled to P * PER particles (ca_fluid_sim_<N>-mpi,
#   bench/CMakeLists.txt WASH_BENCH_SIZES), a square of water whose pieces
#   change shape with P (one cut at 2 ranks, quadrants at 4).
# Prints the time per step (the program's own clock of its steps, "steps
# alone"), and the bytes sent per step from the runtime's end-of-run report:
# by all ranks together and by the busiest rank (halo, migration and sums).
# On a 2-core machine 4 ranks are oversubscribed: times are indicative only.
#   bash bench/mpi_weak_scaling.sh [--bin DIR] [--scenes "strip seed"] [--side 512]
#        [--per N] [--steps S] [--ranks "1 2 4"]
set -u
here=$(cd "$(dirname "$0")" && pwd)
bin=$here/../build/bin per=262144 side=512 steps=5 ranks_list="1 2 4" scenes="strip seed"
while [ $# -gt 0 ]; do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --per) per=$2; shift 2 ;;
    --side) side=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --ranks) ranks_list=$2; shift 2 ;;
    --scenes) scenes=$2; shift 2 ;;
    *) echo "mpi_weak_scaling.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# row SCENE P N PROGRAM [ARGS...]: one table row.
row() {
  local scene=$1 p=$2 n=$3 program=$4
  shift 4
  [ -x "$program" ] || { echo "no $program: build it (see the header of $0)"; exit 1; }
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$p" "$program" "$@" \
    --steps "$steps" --out "$work/out" >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
  seconds=$(sed -n 's/.*steps alone \([0-9.]*\) s.*/\1/p' "$work/log")
  halo=$(sed -n 's/.*halo exchange \([0-9]*\) bytes\/step.*/\1/p' "$work/log")
  migr=$(sed -n 's/.*particle migration \([0-9]*\) bytes\/step.*/\1/p' "$work/log")
  sums=$(sed -n 's/.*sum reductions \([0-9]*\) bytes\/step.*/\1/p' "$work/log")
  busiest=$(sed -n 's/.*at most \([0-9]*\) bytes\/step sent by one rank.*/\1/p' "$work/log")
  copies=$(sed -n 's/.*halo of the last search \([0-9]*\) copies, at most \([0-9]*\) on one rank.*/\1 \/ \2/p' "$work/log")
  printf '%6s %5d %9d %6d %10.3f %12s %12s %12s %14s %18s\n' "$scene" "$p" "$n" "$steps" \
    "$(awk -v s="$seconds" -v k="$steps" 'BEGIN { print s / k }')" "$halo" "$migr" \
    "$((halo + migr + sums))" "$busiest" "$copies"
}

printf '%6s %5s %9s %6s %10s %12s %12s %12s %14s %18s\n' scene ranks particles steps s/step \
  halo_B/step migr_B/step all_B/step busiest_B/step "copies all/most"
for scene in $scenes; do
  for p in $ranks_list; do
    case $scene in
      strip) row strip "$p" $((p * side * side)) "$bin/taylor_green-mpi" "$side" "$p" ;;
      seed) row seed "$p" $((p * per)) "$bin/ca_fluid_sim_$((p * per))-mpi" ;;
      *) echo "mpi_weak_scaling.sh: unknown scene $scene" >&2; exit 2 ;;
    esac
  done
done
