# The generated program of each shared-memory backend named (serial and openmp
# unless named), at 1, 2 and 4 OpenMP threads, must write the same --dump as
# the reference build, byte for byte; the serial one also with the scalar
# neighbour scan forced.
. "$(dirname "$0")/lib.sh"
bin=$1 example=$2 steps=$3
shift 3
backends=("$@")
[ ${#backends[@]} -gt 0 ] || backends=(serial openmp)

expect_exit 0 "$bin/$example-reference" --steps "$steps" --quiet --dump reference.csv --out ref
for backend in "${backends[@]}"; do
  for threads in 1 2 4; do
    # The serial program starts no threads: once is enough.
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
echo "$example: ${backends[*]} (1, 2, 4 threads; serial with both scan paths) identical to the reference after $steps steps"
