# Options and settings that used to hang a run for ever (issue 31, items 8
# and 9): each must now end it, within a bound, with a message that says
# what to change. Every run is under `timeout`, so a regression fails the
# test (exit 124) instead of hanging it.
#   fault_hangs.sh options BIN MPIEXEC BACKEND...    time options past 2^53 multiples
#   fault_hangs.sh end-time BIN MPIEXEC BACKEND...   an end time the time never reaches
. "$(dirname "$0")/lib.sh"
what=$1 bin=$2 mpiexec=$3
shift 3

# launch SCENE BACKEND: the command that runs SCENE's program for BACKEND.
launch() {
  if [ "$2" = mpi ]; then
    [ -n "$mpiexec" ] || fail "no mpiexec for the mpi backend"
    echo "$mpiexec --allow-run-as-root --oversubscribe -np 2 $bin/$1-mpi"
  else
    echo "$bin/$1-$2"
  fi
}

case $what in
options)
  # sim_time sets a time step of about 0.006 and the end time 1: after its
  # first step the time is 10^19 multiples of 1e-22 (10^297 of 1e-300),
  # which the time bookkeeping used to count one by one.
  for backend in reference "$@"; do
    run=$(launch sim_time "$backend")
    for option in --output-dt --checkpoint-dt; do
      for every in 1e-22 1e-300; do
        OMP_NUM_THREADS=1 expect_exit 1 timeout -k 5 60 $run $option $every --quiet --out "o-$backend"
        expect_in out.txt "multiples of $option $every, more than 2^53"
        expect_in out.txt "give $option a larger value"
      done
    done
    # Small multiples far below 2^53 still work: every step crosses some.
    OMP_NUM_THREADS=1 expect_exit 0 timeout -k 5 60 $run --output-dt 1e-10 --end-time 0.03 --quiet \
      --format csv --out "small-$backend"
    [ "$(ls "small-$backend" | wc -l)" -ge 3 ] || fail "$backend: --output-dt 1e-10 wrote $(ls "small-$backend")"
  done
  # Numbers no option can hold are refused before the run (exit 2).
  ref=$bin/sim_time-reference
  expect_exit 2 timeout -k 5 60 "$ref" --steps 99999999999999999999
  expect_in out.txt "option '--steps' expects a non-negative integer"
  expect_exit 2 timeout -k 5 60 "$ref" --end-time 1e400
  expect_in out.txt "option '--end-time' expects a non-negative simulated time"
  for bad in -1 nan inf 3x; do
    expect_exit 2 timeout -k 5 60 "$ref" --watchdog "$bad"
    expect_in out.txt "option '--watchdog' expects a non-negative number of seconds (0: off), got '$bad'"
  done
  echo "fault hangs: time options past 2^53 multiples refused on reference $*"
  ;;
end-time)
  # limits_scene never sets a time step (nor an iteration count): with
  # --end-time alone the time stays 0.
  for backend in reference "$@"; do
    run=$(launch limits_scene "$backend")
    OMP_NUM_THREADS=1 expect_exit 1 timeout -k 5 60 $run --end-time 1 --quiet --out "o-$backend"
    expect_in out.txt "error: at the end of step 1: the simulated time did not advance (t = 0, time step 0, never set) and the run ends only at t = 1: it would never end"
    expect_in out.txt "or give an iteration count (--steps N or wash::set_max_iterations)"
    # With a step count the same run is fine: it ends at that count.
    OMP_NUM_THREADS=1 expect_exit 0 timeout -k 5 60 $run --end-time 1 --steps 3 --quiet --out "o-$backend"
  done
  echo "fault hangs: a time that does not advance toward --end-time stopped on reference $*"
  ;;
*) fail "unknown check '$what'" ;;
esac
