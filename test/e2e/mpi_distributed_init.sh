# Distributed init (backends/mpi/include/wash/mpi/creations.hpp): every rank
# runs the init kernels but stores only its blocks of creation indices, so no
# rank holds more than ceil(N/P) + one block + one scratch row before the
# particles move to their owners. Sedov at 30^3 = 27000 particles: the most
# particles one rank held during init (the end-of-run report) must be the
# whole problem at 1 rank and within that bound at 4 ranks with the default
# block (4096) and at 3 with a small one (100), and the --dump must equal serial's.
. "$(dirname "$0")/lib.sh"
mpiexec=$1 bin=$2 backend=${3:-mpi}
side=30 n=27000 steps=2

expect_exit 0 "$bin/sedov-serial" $side --steps $steps --quiet --dump serial.csv --out serial
# check RANKS BLOCK: the bound on RANKS ranks with blocks of BLOCK, and the dump.
check() {
  local ranks=$1 block=$2
  OMP_NUM_THREADS=1 WASH_MPI_CREATION_BLOCK=$block expect_exit 0 timeout 120 "$mpiexec" \
    --allow-run-as-root --oversubscribe -np "$ranks" "$bin/sedov-$backend" $side --steps $steps \
    --dump mpi.csv --out mpi
  local held
  held=$(sed -n 's/.*at start at most \([0-9]*\) particles held.*/\1/p' out.txt)
  [ -n "$held" ] || { cat out.txt >&2; fail "no 'particles held' in the report at $ranks ranks"; }
  local share=$(((n + ranks - 1) / ranks))
  local bound=$((share + block + 1))
  [ "$ranks" -gt 1 ] || bound=$n
  [ "$held" -le "$bound" ] ||
    fail "$ranks ranks, blocks of $block: a rank held $held particles during init (bound $bound)"
  [ "$held" -ge "$share" ] || fail "$ranks ranks: the report says $held, under the share $share"
  cmp -s serial.csv mpi.csv || fail "$ranks ranks, blocks of $block: the dump differs from serial's"
  echo "$ranks ranks, blocks of $block: at most $held of $n particles on one rank during init (bound $bound)"
}
check 1 4096
check 4 4096
check 3 100
echo "distributed init: ok"
