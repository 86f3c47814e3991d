# --profile and the summary under MPI: rank 0's figures, said so; the table
# has the halo exchange and migration rows besides the kernels and the search.
#   profile_mpi.sh MPIEXEC BIN [BACKEND]
. "$(dirname "$0")/lib.sh"
mpiexec=$1 bin=$2 backend=${3:-mpi}

OMP_NUM_THREADS=1 expect_exit 0 timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe -np 2 \
  "$bin/ca_fluid_sim-$backend" --steps 3 --out o --profile
expect_in out.txt "wash: profile of 3 steps (rank 0 of 2)"
for phase in VelocityUpdate CalculateDensity force_kernel "neighbour search" "halo exchange (MPI)" \
  "particle migration (MPI)"; do
  grep -qE "^  $(sed 's/[()]/\\&/g' <<<"$phase") +[0-9]+ " out.txt ||
    { cat out.txt >&2; fail "no profile row of $phase"; }
done
grep -qE "ns per particle-step wall, CPU [0-9.]+ s, [0-9.]+ ns per particle-step \(rank 0 of 2, 1 thread\)" \
  out.txt || { cat out.txt >&2; fail "the summary does not say whose CPU time it gives"; }
echo "profile under MPI: ok"
