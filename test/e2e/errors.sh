# Runtime errors are messages and a non-zero exit, never a crash or a NaN run.
. "$(dirname "$0")/lib.sh"
bin=$1
scenes=$2

expect_exit 1 "$bin/blowup-reference" --steps 50
expect_in out.txt "error: step 2: after kernel 'Accelerate': field 'vel' of particle 0 is inf"
grep -q "steps of" out.txt && fail "the run went on after the state went bad"
# Translated programs test what a kernel wrote inside its particle loop and
# only then scan for the culprit: the same message, at any thread count.
for build in serial openmp; do
  for threads in 1 2; do
    program="$bin/blowup-$build"
    [ -x "$program" ] || continue
    export OMP_NUM_THREADS=$threads
    expect_exit 1 "$program" --steps 50
    expect_in out.txt "error: step 2: after kernel 'Accelerate': field 'vel' of particle 0 is inf"
    grep -q "steps of" out.txt && fail "$build: the run went on after the state went bad"
  done
done

expect_exit 1 "$bin/misuse-reference" --steps 1
expect_in out.txt "misuse.cpp:21:31: error:"
expect_in out.txt "error: force 'heat' is a scalar but is used here as a vector"
# The smoothing-length rule (scenes/support_errors.cpp), in the reference and,
# when it was built, the translated program: the same messages.
for build in reference serial; do
  program="$bin/support_errors-$build"
  [ "$build" = reference ] || [ -x "$program" ] || continue
  expect_exit 1 "$program" both --quiet
  expect_in out.txt "both set_influence_radius and set_smoothing_length_support were called"
  expect_exit 1 "$program" grow --quiet
  # Step s searches with h = 0.02 * 2^(s-1): the support 2h first passes 0.5
  # (half the box) at s = 5, 2h = 0.64.
  expect_in out.txt "error: step 5: kernel 'Count': a support radius of 0.640000 is more than half the periodic box (axis 0)"
  grep -q "steps of" out.txt && fail "$build: the run went on with a support radius too large for the box"
  expect_exit 1 "$program" none --quiet
  expect_in out.txt "no neighbour rule: call wash::set_influence_radius or wash::set_smoothing_length_support"
done
echo "errors: ok"
