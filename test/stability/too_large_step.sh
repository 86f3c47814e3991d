# A run with a deliberately too-large time step (closed_box.cpp with dt x 50)
# stops early, with a message naming the step, the kernel and the field that
# went bad, and a non-zero exit: it does not run on producing NaN.
#   too_large_step.sh BIN [MPIEXEC]
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=${2:-}

# With dt x 50 particles move 7 spacings per step; the third time step
# (step 4) drives internal energies negative, and the sound speed sqrt(gamma
# (gamma - 1) u) computed by 'Density' is NaN. Every backend computes the same
# bits, so every one stops at the same place.
message="error: step 4: after kernel 'Density': field 'sound_speed' of particle"

check_blowup() { # NAME: out.txt holds the run's output
  expect_in out.txt "$message"
  grep -Eq "error: step 4: after kernel 'Density': field 'sound_speed' of particle [0-9]+ is -?nan$" out.txt ||
    fail "$1: the message does not name the particle and the value: $(grep error: out.txt)"
  grep -q "steps of" out.txt && fail "$1: the run went on to the end after the state went bad"
  [ "$(grep -c '^step=' out.txt)" -eq 3 ] || fail "$1: expected the per-step lines of steps 1-3 only"
  # The blow-up was real: by step 3 the energy had grown hundreds of times.
  local energy0 energy3
  energy0=$(field energy "$(grep '^step=1 ' out.txt)")
  energy3=$(field energy "$(grep '^step=3 ' out.txt)")
  awk -v a="$energy0" -v b="$energy3" 'BEGIN { exit !(b > 100 * a) }' ||
    fail "$1: energy went from $energy0 to $energy3 only"
}

expect_exit 1 "$bin/closed_box-openmp" 50 --steps 2001
check_blowup closed_box-openmp
expect_exit 1 "$bin/closed_box-reference" 50 --steps 2001
check_blowup closed_box-reference
if [ -n "$mpiexec" ]; then
  OMP_NUM_THREADS=1 expect_exit 1 timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe -np 2 \
    "$bin/closed_box-mpi" 50 --steps 2001
  check_blowup "closed_box-mpi (2 ranks)"
fi
# The same program with the normal time step runs to the end.
expect_exit 0 "$bin/closed_box-openmp" 1 --steps 101
expect_in out.txt "wash: 101 steps of 1024 particles"
echo "too large a time step: stopped at step 4 in 'Density', field 'sound_speed'${mpiexec:+ (openmp, reference, mpi)}"
