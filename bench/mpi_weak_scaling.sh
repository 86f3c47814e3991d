#!/bin/bash
# mpi_weak_scaling.sh: weak scaling of the MPI program, a fixed number of
# particles per rank (the seed scene scaled, bench/CMakeLists.txt
# WASH_BENCH_SIZES): ca_fluid_sim_<P*PER>-mpi on P = 1, 2, 4 ranks of 1
# OpenMP thread. Prints the time per step (the program's own clock of its
# steps, "steps alone"), and the bytes sent per step from the runtime's
# end-of-run report: by all ranks together and by the busiest rank (halo,
# migration and sums). At fixed particles per rank the busiest rank's bytes
# should stay flat as ranks are added; on a 2-core machine 4 ranks are
# oversubscribed, so the times are indicative only.
#   bash bench/mpi_weak_scaling.sh [--bin DIR] [--per N] [--steps S] [--ranks "1 2 4"]
set -u
here=$(cd "$(dirname "$0")" && pwd)
bin=$here/../build/bin per=262144 steps=5 ranks_list="1 2 4"
while [ $# -gt 0 ]; do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --per) per=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --ranks) ranks_list=$2; shift 2 ;;
    *) echo "mpi_weak_scaling.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%5s %9s %6s %10s %14s %14s %14s %16s\n' ranks particles steps s/step halo_B/step \
  migr_B/step all_B/step busiest_B/step
for p in $ranks_list; do
  n=$((p * per))
  program=$bin/ca_fluid_sim_$n-mpi
  [ -x "$program" ] || { echo "no $program: configure with -DWASH_BENCH_SIZES=...;$n and build it"; exit 1; }
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$p" "$program" \
    --steps "$steps" --out "$work/out" >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
  seconds=$(sed -n 's/.*steps alone \([0-9.]*\) s.*/\1/p' "$work/log")
  halo=$(sed -n 's/.*halo exchange \([0-9]*\) bytes\/step.*/\1/p' "$work/log")
  migr=$(sed -n 's/.*particle migration \([0-9]*\) bytes\/step.*/\1/p' "$work/log")
  sums=$(sed -n 's/.*sum reductions \([0-9]*\) bytes\/step.*/\1/p' "$work/log")
  busiest=$(sed -n 's/.*at most \([0-9]*\) bytes\/step sent by one rank.*/\1/p' "$work/log")
  printf '%5d %9d %6d %10.3f %14s %14s %14s %16s\n' "$p" "$n" "$steps" \
    "$(awk -v s="$seconds" -v k="$steps" 'BEGIN { print s / k }')" "$halo" "$migr" \
    "$((halo + migr + sums))" "$busiest"
done
