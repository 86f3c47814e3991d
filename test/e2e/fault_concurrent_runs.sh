# Two runs into one folder (scenes/faults.cpp): the second is refused at
# start, with a message naming the first, and the first's output is intact;
# the same for a shared --checkpoint-dir; a killed run's lock refuses nobody;
# every temporary file name is the writing process's own.
#   fault_concurrent_runs.sh BIN [MPIEXEC]
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=${2:-}
program=$bin/faults-reference

# holding PID FILE: waits until the run PID wrote FILE (its first frame,
# written once it holds its folders), then stops it there (SIGSTOP), so that
# it is alive, mid-run, while another run starts.
holding() {
  for _ in $(seq 600); do
    [ -e "$2" ] && break
    kill -0 "$1" 2>/dev/null || fail "the first run ended before it was caught running"
    sleep 0.01
  done
  [ -e "$2" ] || fail "the first run never wrote $2"
  kill -STOP "$1"
  for _ in $(seq 100); do
    grep -q "^State:.*T" "/proc/$1/status" && return
    sleep 0.01
  done
  fail "the first run could not be stopped mid-run"
}

# The first run, alone, for what its files must be.
expect_exit 0 "$program" none --quiet --steps 4000 --output-every 1000 --out alone --dump alone.csv

# The same run, and a second one into its folder while it runs.
"$program" none --quiet --steps 4000 --output-every 1000 --out shared --dump first.csv \
  >first.txt 2>&1 &
first=$!
holding "$first" shared/wash_000000.vtp
expect_exit 1 "$program" none --quiet --steps 5 --out shared
kill -CONT "$first"
expect_in out.txt "error: output directory 'shared' is in use by another run: pid $first on host"
expect_in out.txt "give this one another --out"
wait "$first" || { cat first.txt >&2; fail "the first run failed once another had tried its folder"; }
cmp -s alone.csv first.csv || fail "the first run's dump differs from its run alone"
for f in alone/*; do
  cmp -s "$f" "shared/${f##*/}" || fail "shared/${f##*/} differs from the first run's alone"
done
[ "$(ls -A shared)" = "$(ls -A alone)" ] || fail "the folder holds other files: $(ls -A shared)"

# A shared --checkpoint-dir: refused the same way. The first run then killed
# (SIGKILL): its lock goes with it, and a new run there starts, removing the
# partial files of dead processes (not those of live ones).
"$program" none --quiet --steps 100000000 --output-every 100000000 --checkpoint-every 1000 \
  --checkpoint-dir ck --out a >a.txt 2>&1 &
first=$!
holding "$first" a/wash_000000.vtp
expect_exit 1 "$program" none --quiet --steps 5 --out b --checkpoint-dir ck
expect_in out.txt "error: checkpoint directory 'ck' is in use by another run: pid $first on host"
expect_in out.txt "give this one another --checkpoint-dir"
[ ! -e b/wash_000000.vtp ] || fail "the refused run wrote frames"
{ kill -KILL "$first" && wait "$first"; } 2>/dev/null
sh -c 'echo $$ >dead.pid'
dead=$(cat dead.pid)
touch "a/wash_000000.vtp.wash-partial.$dead" "a/wash_000000.vtp.wash-partial.$$"
expect_exit 0 "$program" none --quiet --steps 5 --out a --checkpoint-dir ck --checkpoint-every 5
[ -f ck/checkpoint_000005/index.wck ] || fail "no checkpoint after the killed run's: $(ls ck)"
[ ! -e "a/wash_000000.vtp.wash-partial.$dead" ] || fail "a dead process's partial file was left"
[ -e "a/wash_000000.vtp.wash-partial.$$" ] || fail "a live process's partial file was removed"
[ ! -e a/.wash-lock ] && [ ! -e ck/.wash-lock ] || fail "a run that ended left its lock file"

# Temporary names: <file>.wash-partial.<pid of the writer>, for frames, the
# series, the dump and checkpoint files (rename calls, seen by strace).
if strace -f -o trace.txt -e trace=rename,renameat,renameat2 true 2>/dev/null; then
  strace -f -o trace.txt -e trace=rename,renameat,renameat2 \
    "$program" none --quiet --steps 4 --output-every 2 --checkpoint-every 2 --out names \
    --dump names.csv >out.txt 2>&1 || { cat out.txt >&2; fail "the traced run failed"; }
  renames=$(grep -c 'wash-partial' trace.txt)
  [ "$renames" -ge 8 ] || fail "only $renames temporary files renamed: $(cat trace.txt)"
  awk '/wash-partial/ {
         n = split($0, q, "\""); from = q[2]; to = q[4]
         if (from != to ".wash-partial." $1) { print; bad = 1 }
       } END { exit bad }' trace.txt >bad.txt ||
    fail "temporary names that are not <file>.wash-partial.<pid>: $(cat bad.txt)"
else
  echo "concurrent runs: strace cannot trace here; temporary names not checked"
fi

# MPI: rank 0 alone takes the lock (the ranks do not refuse each other), and
# a job into a folder another run holds is refused.
if [ -n "$mpiexec" ] && [ -x "$bin/faults-mpi" ]; then
  mpi() {
    OMP_NUM_THREADS=1 timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe -np 2 \
      "$bin/faults-mpi" none --quiet "$@"
  }
  mpi --steps 5 --out mpi-alone >out.txt 2>&1 || { cat out.txt >&2; fail "a 2-rank run failed"; }
  "$program" none --quiet --steps 100000000 --output-every 100000000 --out mpi >first.txt 2>&1 &
  first=$!
  holding "$first" mpi/wash_000000.vtp
  mpi --steps 5 --out mpi >out.txt 2>&1
  got=$?
  { kill -KILL "$first" && wait "$first"; } 2>/dev/null
  [ "$got" -ne 0 ] || fail "a 2-rank run into a folder another run holds was not refused"
  expect_in out.txt "error: output directory 'mpi' is in use by another run: pid $first on host"
fi
echo "concurrent runs: the second refused, the first intact"
