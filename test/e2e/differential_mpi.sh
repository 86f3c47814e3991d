# A distributed backend's program (mpi unless named) at 1, 2, 3 and 4 ranks
# must write the same --dump as the serial program, byte for byte.
. "$(dirname "$0")/lib.sh"
mpiexec=$1 bin=$2 example=$3 steps=$4 backend=${5:-mpi}

expect_exit 0 "$bin/$example-serial" --steps "$steps" --quiet --dump serial.csv --out serial
for ranks in 1 2 3 4; do
  OMP_NUM_THREADS=1 expect_exit 0 timeout 300 "$mpiexec" --allow-run-as-root --oversubscribe \
    -np "$ranks" "$bin/$example-$backend" --steps "$steps" --quiet --dump "mpi-$ranks.csv" --out "mpi-$ranks"
  cmp -s serial.csv "mpi-$ranks.csv" ||
    fail "$example-$backend on $ranks ranks differs from the serial program after $steps steps: $(cmp serial.csv "mpi-$ranks.csv")"
done
echo "$example: mpi on 1, 2, 3 and 4 ranks identical to serial after $steps steps"
