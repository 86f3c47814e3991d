# The wash program options, as a build of the seed example sees them: the
# reference build or a translated one (second argument "generated"), which
# must behave the same, down to the summary line with the steps' own time.
. "$(dirname "$0")/lib.sh"
sim=$1

expect_exit 0 "$sim" --help
expect_in out.txt "--output-every K"
[ ! -e out ] || fail "--help wrote output"

# Options are removed from argv: the seed reads argv[1] and argv[2] as names.
expect_exit 0 "$sim" myrun --steps 10 frames --out o1 --output-every 4 --format csv
for step in 000000 000004 000008 000010; do
  [ -f "o1/frames_$step.csv" ] || fail "missing o1/frames_$step.csv"
done
[ ! -e o1/frames_000005.csv ] || fail "unexpected frame 5"
expect_in out.txt "'myrun', 4032 particles, 2D, double"
expect_in out.txt "10 steps"
expect_in out.txt "wash: 10 steps of 4032 particles in "
# The steps' wall and CPU time, each per particle-step, and whose CPU time.
grep -qE "; steps alone [0-9]+\.[0-9]{3} s, [0-9]+\.[0-9] ns per particle-step wall, CPU [0-9]+\.[0-9]{3} s, [0-9]+\.[0-9] ns per particle-step \(this process, [0-9]+ threads?\); output in o1$" out.txt \
  || { cat out.txt >&2; fail "no wall and CPU time of the steps alone in the summary"; }
grep -q "profile" out.txt && fail "a profile without --profile"

# --profile: a table of where the steps went, one row per kernel, the search
# and output, even with --quiet; the results are the same.
expect_exit 0 "$sim" --steps 3 --out o4 --dump profiled.csv --quiet --profile
expect_in out.txt "wash: profile of 3 steps (this process)"
grep -qE "^  phase +calls +wall s +ms/step +% wall +ns/particle +CPU s$" out.txt ||
  { cat out.txt >&2; fail "no profile table header"; }
for phase in VelocityUpdate CalculateDensity force_kernel UpdatePositions HandleCollisions; do
  grep -qE "^  $phase +3 " out.txt || { cat out.txt >&2; fail "no profile row of $phase, 3 calls"; }
done
grep -qE "^  neighbour search.* +[0-9]+ " out.txt || { cat out.txt >&2; fail "no neighbour search row"; }
grep -qE "^  output \(frames\) +1 " out.txt || { cat out.txt >&2; fail "no output row"; }
grep -qE "^  total +[0-9]+ " out.txt || { cat out.txt >&2; fail "no total row"; }
grep -q "steps alone" out.txt && fail "--quiet --profile printed the summary"
expect_exit 0 "$sim" --steps 3 --out o5 --dump unprofiled.csv --quiet
cmp -s profiled.csv unprofiled.csv || fail "--profile changed the results"

# VTK: .vtp frames plus a .pvd series; final state only by default.
expect_exit 0 "$sim" --steps=3 --out o2
[ -f o2/serial_test_000003.vtp ] || fail "missing final .vtp"
expect_in o2/serial_test.pvd 'file="serial_test_000003.vtp"'
[ "$(ls o2 | wc -l)" -eq 2 ] || fail "expected only the final frame and the series"

# --dump matches the final CSV frame but for acc, which frames alone hold;
# --quiet prints only what the simulation prints.
expect_exit 0 "$sim" --steps 2 --out o3 --format csv --dump d.csv --quiet
head -1 o3/serial_test_000002.csv | grep -q ',vx,vy,acc_x,acc_y,density,' ||
  fail "the CSV frame has no acc after vel: $(head -1 o3/serial_test_000002.csv)"
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) keep[i] = $i !~ /^acc_/ }
  { line = ""; for (i = 1; i <= NF; i++) if (keep[i]) line = line (line == "" ? "" : ",") $i; print line }' \
  o3/serial_test_000002.csv >frame-without-acc.csv
cmp -s d.csv frame-without-acc.csv || fail "--dump differs from the final frame (acc left out)"
head -1 d.csv | grep -qx 'id,x,y,vx,vy,density,mass,smoothing_length,nearDensity,predictedPosition_x,predictedPosition_y,pressure_x,pressure_y,position_x,position_y,viscosity_x,viscosity_y' \
  || fail "dump header: $(head -1 d.csv)"
grep -q "wash" out.txt && fail "--quiet still printed the run header"

# Bad options: a message and exit status 2, before the simulation runs.
expect_exit 2 "$sim" --steps many
expect_in out.txt "option '--steps' expects a non-negative integer, got 'many'"
expect_exit 2 "$sim" --format png
expect_in out.txt "'vtk', 'csv' or 'hdf5'"
expect_exit 2 "$sim" --bogus
expect_in out.txt "unknown option '--bogus'"
grep -q "Calculated Time Step" out.txt && fail "the simulation ran despite a bad option"

# An unusable output directory fails before the run, with a message.
touch blocker
expect_exit 1 "$sim" --steps 1 --out blocker/sub
expect_in out.txt "error: cannot create output directory 'blocker/sub'"
echo "program options: ok"
