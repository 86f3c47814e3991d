# Simulated time: frames at the times --output-dt asks for (within one step),
# --end-time stopping at the iteration that reaches it, wash::stop() still
# ending such a run, the same dumps and step counts on every backend, and
# standard output flushed while the run goes on.
#   sim_time.sh BIN MPIEXEC BACKEND...   (MPIEXEC may be "" when there is no MPI)
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=$2
shift 2
ref=$bin/sim_time-reference
py=/usr/bin/python3

# check_frames DIR END OUTPUT_DT: the frames DIR holds (CSV) are step 0, the
# last step, and exactly those whose step crossed a multiple of OUTPUT_DT; the
# last step is the first to reach END. Prints the number of steps.
check_frames() {
  "$py" - "$@" <<'PY'
import csv, glob, math, os, re, sys
folder, end, every = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
frames = {}
for path in glob.glob(os.path.join(folder, "sim_time_*.csv")):
    step = int(re.search(r"_(\d+)\.csv$", path).group(1))
    rows = list(csv.DictReader(open(path)))
    times = {r["time"] for r in rows}
    assert len(times) == 1, f"{path}: particles disagree on the time: {times}"
    frames[step] = (float(rows[0]["start"]), float(rows[0]["time"]))
steps = sorted(frames)
def fail(msg):
    print(f"FAIL: {msg}; frames (step: start, end) {[(s, frames[s]) for s in steps]}", file=sys.stderr)
    sys.exit(1)
def crossed(start, end):  # a multiple k * every in (start, end]
    return any(start < k * every <= end
               for k in range(max(0, math.floor(start / every) - 1), math.floor(end / every) + 2))
if not steps or steps[0] != 0:
    fail("no frame 0")
last = steps[-1]
start, t = frames[last]
if not (t >= end and start < end):
    fail(f"the last step {last} ends at t = {t!r} (from {start!r}), not the first to reach {end!r}")
for s in steps[1:-1]:
    if not crossed(*frames[s]):
        fail(f"frame {s} (t from {frames[s][0]!r} to {frames[s][1]!r}) crossed no multiple of {every!r}")
# Every multiple up to the end has its frame, written at the end of the step
# that crossed it (so at most one step late).
k = 1
while k * every <= frames[last][1]:
    if not any(frames[s][0] < k * every <= frames[s][1] for s in steps[1:]):
        fail(f"no frame for t = {k * every!r}")
    k += 1
print(last)
PY
}

# 1. Frames by time and the end time, on the reference.
expect_exit 0 "$ref" --end-time 0.5 --output-dt 0.1 --format csv --out ref --dump ref.csv
expect_in out.txt "until t = 0.5"
last=$(check_frames ref 0.5 0.1) || fail "reference frames (above)"
expect_in out.txt "wash: $last steps of 64 particles"
[ "$(ls ref | wc -l)" -ge 6 ] || fail "expected at least 6 frames, got $(ls ref)"

# 2. The same steps, frames and dump on every backend.
for backend in "$@"; do
  run=("$bin/sim_time-$backend")
  if [ "$backend" = mpi ]; then
    [ -n "$mpiexec" ] || fail "no mpiexec for the mpi backend"
    run=("$mpiexec" --allow-run-as-root --oversubscribe -np 2 "$bin/sim_time-mpi")
  fi
  OMP_NUM_THREADS=2 expect_exit 0 timeout 120 "${run[@]}" --end-time 0.5 --output-dt 0.1 \
    --format csv --out "$backend" --dump "$backend.csv"
  expect_in out.txt "wash: $last steps of 64 particles"
  cmp -s ref.csv "$backend.csv" || fail "$backend's dump differs from the reference's: $(cmp ref.csv "$backend.csv")"
  [ "$(ls ref)" = "$(ls "$backend")" ] || fail "$backend wrote frames $(ls "$backend"), the reference $(ls ref)"
  for f in ref/*.csv; do
    cmp -s "$f" "$backend/${f#ref/}" || fail "$backend's frame ${f#ref/} differs from the reference's"
  done
done

# 3. The end time of main (set_end_time(1)), no step count given: the last
# step is shortened to land on it exactly.
expect_exit 0 "$ref" --quiet --dump main.csv --out main
"$py" -c "import csv,sys; t={r['time'] for r in csv.DictReader(open('main.csv'))}; print(t); sys.exit(t!={'1'})" >t.txt ||
  fail "the set_end_time(1) run ended at t = $(cat t.txt), not exactly 1"

# 4. wash::stop() still ends a run that has an end time: the first iteration
# starting at t >= 0.3 is the last.
expect_exit 0 "$ref" 0.3 --end-time 0.5 --output-every 1 --format csv --out stop
"$py" - stop <<'PY' || fail "wash::stop() did not end the run at the first step starting at t >= 0.3"
import csv, glob, sys
frames = sorted(glob.glob(sys.argv[1] + "/sim_time_*.csv"))
before, last = (next(csv.DictReader(open(f))) for f in frames[-2:])
sys.exit(0 if float(before["start"]) < 0.3 <= float(last["start"]) and float(last["time"]) < 0.5 else 1)
PY

# 5. Bad values of the new options.
expect_exit 2 "$ref" --end-time soon
expect_in out.txt "option '--end-time' expects a non-negative simulated time, got 'soon'"
expect_exit 2 "$ref" --output-dt 0
expect_in out.txt "option '--output-dt' expects a positive simulated time, got '0'"

# 6. Standard output reaches a file while the run goes on: the first step's
# line must be there long before a 10 s run ends.
"$ref" inf slow --steps 5000 --end-time 1e9 --quiet --out slow >slow.txt 2>&1 &
pid=$!
for _ in $(seq 50); do
  grep -q "first step done" slow.txt && break
  sleep 0.1
done
found=$(grep -c "first step done" slow.txt)
kill -0 "$pid" 2>/dev/null || fail "the 10 s run had ended: the check proves nothing"
kill "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
[ "$found" = 1 ] || fail "nothing printed reached the file within 5 s (stdout not flushed)"
echo "sim_time: frames by time, end time, stop() and flushing on reference $*"
