# An exception thrown inside a kernel (scenes/faults.cpp) ends the run with
# its message and exit status 1 on every backend, at any thread or rank
# count: never SIGABRT (an exception escaping an OpenMP region), never a hang.
# One that is no std::exception (`throw 42;`) is named by its type.
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=${2:-}

check() { # check WHAT EXPECTED-MESSAGE CMD...: exit status 1 and the message
  local what=$1 message=$2; shift 2
  timeout 120 "$@" --quiet >out.txt 2>&1
  local got=$?
  [ "$got" -eq 1 ] || { cat out.txt >&2; fail "$what: exit status $got, expected 1"; }
  expect_in out.txt "error: $message"
  grep -q "terminate called\|Aborted\|signal" out.txt && { cat out.txt >&2; fail "$what: aborted"; }
  return 0
}

update="particle 141 refuses to move"
force="particle 233 has 8 neighbours, too many"
int="an exception of type 'int' thrown in step 1, with 400 particles"
check reference "$update" "$bin/faults-reference" update
check reference "$force" "$bin/faults-reference" force
check reference "$int" "$bin/faults-reference" int
for build in serial openmp; do
  [ -x "$bin/faults-$build" ] || continue
  for threads in 1 2 4; do
    OMP_NUM_THREADS=$threads check "$build x$threads" "$update" "$bin/faults-$build" update
    OMP_NUM_THREADS=$threads check "$build x$threads" "$force" "$bin/faults-$build" force
    OMP_NUM_THREADS=$threads check "$build x$threads" "$int" "$bin/faults-$build" int
  done
  "$bin/faults-$build" none --quiet --out run >out.txt 2>&1 || { cat out.txt >&2; fail "$build: clean run failed"; }
done
if [ -x "$bin/faults-mpi" ] && [ -n "$mpiexec" ]; then
  for np in 1 2 3; do
    for where in update force int; do
      message=$update
      [ $where = force ] && message=$force
      [ $where = int ] && message="an exception of type 'int' thrown in step 1"
      OMP_NUM_THREADS=2 check "mpi -np $np" "$message" \
        "$mpiexec" --allow-run-as-root --oversubscribe -np $np "$bin/faults-mpi" $where
    done
  done
fi
echo "kernel errors: ok"
