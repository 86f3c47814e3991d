# A stopped rank (SIGSTOP) ends the whole MPI job within the watchdog's bound,
# with a message that names the rank (issue 31, item 10); a rank that only
# pauses for less than the watchdog time does not.
#   fault_mpi_watchdog.sh MPIEXEC BIN
. "$(dirname "$0")/lib.sh"
mpiexec=$1 bin=$2
prog=$bin/ca_fluid_sim-mpi

# rank_pid TAG RANK: the pid of rank RANK of the job whose --out is TAG.
rank_pid() {
  local pid
  for pid in $(pgrep -f "ca_fluid_sim-mpi .*--out $1\$"); do
    tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2" && echo "$pid"
  done
}

# start TAG WATCHDOG: a long job of 3 ranks in the background, in $job.
start() {
  OMP_NUM_THREADS=1 timeout -k 5 120 "$mpiexec" --allow-run-as-root --oversubscribe -np 3 "$prog" \
    --steps 1000000 --quiet --watchdog "$2" --out "$work/$1" >"$1.txt" 2>&1 &
  job=$!
  for _ in $(seq 100); do
    [ -n "$(rank_pid "$work/$1" 1)" ] && [ -d "$work/$1" ] && break
    sleep 0.1
  done
  victim=$(rank_pid "$work/$1" 1)
  [ -n "$victim" ] || { cat "$1.txt" >&2; fail "no rank 1 found for job $1"; }
  sleep 1 # into the steps
}

# 1. Rank 1 stopped for good: the job ends within twice the watchdog time
# (no progress for 3 s, then no answer for 3 s), plus start-up and slack.
start stopped 3
kill -STOP "$victim"
began=$(date +%s)
wait "$job"
status=$? took=$(($(date +%s) - began))
[ "$status" -ne 124 ] && [ "$status" -ne 137 ] ||
  fail "the job with a stopped rank hung (killed by timeout after 120 s)"
[ "$status" -ne 0 ] || fail "the job with a stopped rank exited 0"
[ "$took" -le 30 ] || fail "the job took $took s to end after rank 1 stopped (watchdog 3 s)"
expect_in stopped.txt "error: rank 1 stopped answering: no answer in 3 s"
expect_in stopped.txt "(the MPI watchdog: --watchdog SECONDS, 0 turns it off)"
# alive PID: the process is there and not a zombie (one nobody reaped).
alive() { [ -r "/proc/$1/stat" ] && ! grep -q '^[0-9]* ([^)]*) Z' "/proc/$1/stat"; }
for _ in $(seq 50); do
  alive "$victim" || break
  sleep 0.1
done
alive "$victim" && fail "the stopped rank $victim is still running 5 s after the job ended"

# 2. Rank 1 paused for 1 s, less than the watchdog's 4 s: the job goes on,
# and a SIGTERM ends it as usual (a checkpoint, exit 75).
start paused 4
kill -STOP "$victim"
sleep 1
kill -CONT "$victim"
sleep 6
kill -0 "$job" 2>/dev/null || { cat paused.txt >&2; fail "the job ended after a 1 s pause (watchdog 4 s)"; }
kill -TERM $(pgrep -P "$job") # mpirun, which passes it to every rank
wait "$job"
status=$?
[ "$status" -ne 124 ] && [ "$status" -ne 137 ] || fail "the paused job did not stop on SIGTERM"
grep -q "stopped answering" paused.txt && { cat paused.txt >&2; fail "the watchdog named a rank that only paused"; }
echo "mpi watchdog: a stopped rank ends the job in $took s, named; a pause does not"
