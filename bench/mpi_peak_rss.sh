#!/bin/bash
# mpi_peak_rss.sh: the peak resident memory of every MPI rank (GNU time's %M,
# KiB) at 1, 2 and 4 ranks, 1 OpenMP thread each, for the 1M-particle seed
# (ca_fluid_sim_1048576-mpi, bench/CMakeLists.txt) and Sedov 50^3
# (sedov-mpi 50), 2 steps, and each rank's ratio to the bound of issue 21:
# 1.3 x (the 1-rank peak) / P + 30 MiB. A ratio at or under 1 meets it.
#   bash bench/mpi_peak_rss.sh [--bin DIR] [--ranks "1 2 4"] [--steps S]
# (ONLY_SEED=1 skips Sedov.)
set -u
here=$(cd "$(dirname "$0")" && pwd)
bin=$here/../build/bin ranks_list="1 2 4" steps=2
while [ $# -gt 0 ]; do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --ranks) ranks_list=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    *) echo "mpi_peak_rss.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
missed=0

# measure NAME PROGRAM [ARGS...]: one table row per rank count.
measure() {
  local name=$1 program=$2
  shift 2
  [ -x "$bin/$program" ] || { echo "$name: no $bin/$program (build it)"; missed=1; return; }
  local one=""
  for p in $ranks_list; do
    rm -rf "$work/out" "$work"/rss.*
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$p" \
      sh -c "exec /usr/bin/time -f %M -o '$work/rss.'\$OMPI_COMM_WORLD_RANK \
        '$bin/$program' $* --steps $steps --quiet --out '$work/out'" \
      >"$work/log" 2>&1 || { cat "$work/log"; echo "$name at $p ranks failed"; missed=1; return; }
    local line="" worst=0 r kib
    [ -n "$one" ] || one=$(cat "$work/rss.0")
    # bound in KiB: 1.3 * one / p + 30 MiB
    local bound
    bound=$(awk -v one="$one" -v p="$p" 'BEGIN { printf "%.0f", 1.3 * one / p + 30 * 1024 }')
    for ((r = 0; r < p; r++)); do
      kib=$(tail -n 1 "$work/rss.$r")
      line+=$(awk -v k="$kib" -v b="$bound" 'BEGIN { printf " %7.1f MiB (%.2f)", k / 1024, k / b }')
      worst=$(awk -v k="$kib" -v b="$bound" -v w="$worst" 'BEGIN { r = k / b; print (r > w ? r : w) }')
    done
    awk -v w="$worst" 'BEGIN { exit !(w > 1) }' && missed=1
    printf '%-14s %d ranks: bound %7.1f MiB; per rank (ratio to bound):%s\n' "$name" "$p" \
      "$(awk -v b="$bound" 'BEGIN { printf "%.1f", b / 1024 }')" "$line"
  done
}

measure "seed 1M" ca_fluid_sim_1048576-mpi
[ -n "${ONLY_SEED:-}" ] || measure "sedov 50^3" sedov-mpi 50
[ "$missed" -eq 0 ] && echo "every rank within the bound" || echo "some rank over the bound (ratio > 1)"
