# The generated serial and OpenMP programs (1, 2 and 4 threads) must write
# the same --dump as the reference build, byte for byte; the serial one also
# with the scalar neighbour scan forced.
. "$(dirname "$0")/lib.sh"
bin=$1 example=$2 steps=$3

expect_exit 0 "$bin/$example-reference" --steps "$steps" --quiet --dump reference.csv --out ref
for backend in serial openmp; do
  for threads in 1 2 4; do
    [ "$backend" = serial ] && [ "$threads" != 1 ] && continue
    OMP_NUM_THREADS=$threads expect_exit 0 "$bin/$example-$backend" --steps "$steps" --quiet \
      --dump "$backend-$threads.csv" --out "$backend-$threads"
    cmp -s reference.csv "$backend-$threads.csv" ||
      fail "$example-$backend with $threads threads differs from the reference after $steps steps: $(cmp reference.csv "$backend-$threads.csv")"
  done
done
# The neighbour scan takes an AVX2 path where the machine has one; the
# scalar path must give the same dump.
WASH_SCALAR_SCAN=1 expect_exit 0 "$bin/$example-serial" --steps "$steps" --quiet \
  --dump serial-scalar-scan.csv --out serial-scalar-scan
cmp -s reference.csv serial-scalar-scan.csv ||
  fail "$example-serial with WASH_SCALAR_SCAN=1 differs from the reference after $steps steps: $(cmp reference.csv serial-scalar-scan.csv)"
[ "$(wc -l < reference.csv)" -gt 100 ] || fail "suspiciously few particles in the dump"
echo "$example: serial (both scan paths) and openmp (1, 2, 4 threads) identical to the reference after $steps steps"
