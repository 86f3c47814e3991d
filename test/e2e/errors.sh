# Runtime errors are messages and a non-zero exit, never a crash or a NaN run.
. "$(dirname "$0")/lib.sh"
bin=$1
scenes=$2

expect_exit 1 "$bin/blowup-reference" --steps 50
expect_in out.txt "error: step 2: after kernel 'Accelerate': field 'vel' of particle"
grep -q "steps of" out.txt && fail "the run went on after the state went bad"

expect_exit 1 "$bin/misuse-reference" --steps 1
expect_in out.txt "misuse.cpp:21:31: error:"
expect_in out.txt "error: force 'heat' is a scalar but is used here as a vector"
echo "errors: ok"
