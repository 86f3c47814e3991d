# Out of memory (scenes/faults.cpp asked for 10^12 particles, under a 1 GB
# address-space limit) is a message that says what was being allocated and
# how much, with exit status 1: not a bare "std::bad_alloc".
. "$(dirname "$0")/lib.sh"
bin=$1
pattern="error: out of memory allocating [0-9]+ particles x [0-9]+ bytes \([0-9.e+]+ GiB\) for the particle store \(create_particle\)"
for build in reference serial openmp; do
  program="$bin/faults-$build"
  [ "$build" = reference ] || [ -x "$program" ] || continue
  (ulimit -v 1000000 && OMP_NUM_THREADS=2 timeout 120 "$program" none 1e12 --quiet --out run) >out.txt 2>&1
  status=$?
  [ $status -eq 1 ] || { cat out.txt >&2; fail "$build: exit status $status, expected 1"; }
  grep -qE "$pattern" out.txt || { cat out.txt >&2; fail "$build: no out-of-memory message naming the allocation"; }
done
echo "out of memory: ok"
