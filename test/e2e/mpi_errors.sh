# A failure on one rank, or bad input, ends the whole MPI job with a message;
# it never hangs (timeout) or runs on.
. "$(dirname "$0")/lib.sh"
mpiexec=$1 bin=$2 backend=${3:-mpi}
run() { OMP_NUM_THREADS=1 timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe "$@"; }

# Bad options: every rank refuses, with a message.
run -np 2 "$bin/ca_fluid_sim-$backend" --steps lots >out.txt 2>&1 && fail "bad option accepted"
[ $? -ne 124 ] || fail "the job hung on a bad option"
expect_in out.txt "option '--steps' expects a non-negative integer, got 'lots'"

# An unwritable output directory on rank 0, the only rank that writes.
touch blocker
run -np 3 "$bin/ca_fluid_sim-$backend" --steps 2 --out blocker/sub >out.txt 2>&1 && fail "unwritable directory accepted"
[ $? -ne 124 ] || fail "the job hung when rank 0 failed"
expect_in out.txt "cannot create output directory 'blocker/sub'"

# A state that goes non-finite (test/e2e/scenes/blowup.cpp, translated for MPI).
run -np 2 "$bin/blowup-$backend" --steps 50 >out.txt 2>&1 && fail "non-finite state accepted"
[ $? -ne 124 ] || fail "the job hung after a rank failed"
expect_in out.txt "error: step 2: after kernel 'Accelerate': field 'vel' of particle"
# Init kernels that create different particles on different ranks
# (test/e2e/scenes/nondeterministic_init.cpp): every rank compares a digest of
# what it created and the job stops with a message.
run -np 3 "$bin/nondeterministic_init-$backend" >out.txt 2>&1 && fail "rank-dependent init accepted"
[ $? -ne 124 ] || fail "the job hung on a rank-dependent init"
expect_in out.txt "the init kernels created different particles on different ranks"
expect_in out.txt "must be deterministic"
echo "mpi errors: ok"
