# Sedov, a variable time step, run by simulated time: with --end-time and
# --output-dt its frames are those of the first steps to reach each multiple
# of the output interval (so at most one step late), step 0 and the last step,
# which is the one that reaches the end time. The step times come from a run
# of the same scene with a frame every step.
#   sedov_output_dt.sh BIN
. "$(dirname "$0")/lib.sh"
bin=$1
program=$bin/sedov-serial
expect_exit 0 "$program" 8 --end-time 0.03 --output-every 1 --quiet --out every
expect_exit 0 "$program" 8 --end-time 0.03 --output-dt 0.01 --quiet --out bytime
/usr/bin/python3 - every/sedov.pvd bytime/sedov.pvd 0.03 0.01 <<'PY' || fail "sedov's frames by time (above)"
import sys, xml.etree.ElementTree as ET
def times(path):
    return [(float(d.get("timestep")), d.get("file")) for d in ET.parse(path).iter("DataSet")]
every, bytime = times(sys.argv[1]), times(sys.argv[2])
end, dt = float(sys.argv[3]), float(sys.argv[4])
steps = [t for t, _ in every]
assert len(steps) > 6, f"too few steps to test: {steps}"
assert steps[-1] >= end and steps[-2] < end, f"the last step does not reach {end}: {steps[-3:]}"
expected = {0.0, steps[-1]}
k = 1
while k * dt <= steps[-1]:
    expected.add(next(t for t in steps if t >= k * dt))
    k += 1
got = [t for t, _ in bytime]
assert sorted(set(got)) == got, f"frames out of order or repeated: {got}"
assert set(got) == expected, f"frames at {got}, expected {sorted(expected)} (steps {steps})"
# Each frame by time is the every-step run's frame of the same step.
files = dict((f, t) for t, f in every)
for t, f in bytime:
    assert files.get(f) == t, f"{f} at t = {t} is not that step's frame ({files.get(f)})"
print(f"sedov: {len(got)} frames by time at {got}")
PY
