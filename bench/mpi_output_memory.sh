#!/bin/bash
# mpi_output_memory.sh PROGRAM [RANKS] [ARGS...]: each rank's peak memory
# (Maximum resident set size of /usr/bin/time -v, KiB) for a run of PROGRAM at
# RANKS (default 4) MPI ranks, and rank 0's over the largest other rank's.
#   bash bench/mpi_output_memory.sh build/bin/ca_fluid_sim_1048576-mpi 4 \
#     --steps 2 --output-every 1 --format hdf5
set -u
program=$1 ranks=${2:-4}
shift 2 || shift $#
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} mpirun --allow-run-as-root --oversubscribe -np "$ranks" \
  sh -c "exec /usr/bin/time -v -o '$work/rss.'\$OMPI_COMM_WORLD_RANK $program --out '$work/out' --quiet $*" \
  >"$work/log" 2>&1 || { cat "$work/log"; echo "the run failed"; exit 1; }
line="max RSS KiB per rank:"
for ((r = 0; r < ranks; r++)); do
  line+=" $(awk '/Maximum resident/ {print $6}' "$work/rss.$r")"
done
echo "$line"
echo "$line" | awk '{ m = 0; for (i = 7; i <= NF; i++) if ($i > m) m = $i;
  printf "rank 0 / largest other rank: %.3f\n", $6 / (m ? m : 1) }'
