# The .pvd series is on disk after every frame (issue 31): a run killed by
# SIGKILL, or stopped by SIGTERM (exit 75), leaves a well-formed .pvd that
# lists exactly the frames on disk, each of which VTK's reader reads. The
# kill lands while the run sleeps in a kernel (the scene's "slow" mode), not
# between a frame and its series, so that "exactly" holds every time.
#   fault_pvd_kill.sh BIN [MPIEXEC]
. "$(dirname "$0")/lib.sh"
bin=$1
py=/usr/bin/python3
"$py" -c "import vtk" 2>/dev/null || { echo "SKIP: vtk (python3-vtk9) is not installed"; exit 77; }

# check DIR: the .pvd parses (Python's XML parser and VTK's) and
# lists the .vtp files of DIR, every one, in step order; each reads.
check() {
  "$py" - "$1" <<'PY' || fail "the .pvd of $1 is not the series of its frames (above)"
import glob, os, sys
import xml.etree.ElementTree as ET
import vtk
d = sys.argv[1]
pvd = os.path.join(d, "sim_time.pvd")
if not os.path.exists(pvd):
    sys.exit(f"no {pvd}; files: {sorted(os.listdir(d))}")
listed = [e.get("file") for e in ET.parse(pvd).getroot().iter("DataSet")]
on_disk = sorted(os.path.basename(f) for f in glob.glob(os.path.join(d, "sim_time_*.vtp")))
if listed != on_disk or len(listed) < 3:
    sys.exit(f"{pvd} lists {listed}, the frames on disk are {on_disk}")
parser = vtk.vtkXMLDataParser()  # VTK's own XML parser, as its readers use
parser.SetFileName(pvd)
if not parser.Parse():
    sys.exit(f"VTK's XML parser cannot parse {pvd}")
collection = parser.GetRootElement().GetNestedElement(0)
files = [collection.GetNestedElement(i).GetAttribute("file")
         for i in range(collection.GetNumberOfNestedElements())]
if files != listed:
    sys.exit(f"VTK's XML parser reads {files} from {pvd}")
for name in listed:
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(os.path.join(d, name))
    r.Update()
    if r.GetOutput().GetNumberOfPoints() != 64:
        sys.exit(f"{name}: {r.GetOutput().GetNumberOfPoints()} points, expected 64")
PY
}

# run NAME DIR: the slow scene, a frame every other step, in the background.
run() {
  "$bin/sim_time-$1" inf slow --steps 100000 --end-time 1e9 --output-every 2 --quiet --out "$2" \
    >run.txt 2>&1 &
  pid=$!
  for _ in $(seq 200); do
    [ "$(ls "$2" 2>/dev/null | grep -c '\.vtp$')" -ge 6 ] && return
    sleep 0.05
  done
  fail "$1 wrote no frames: $(cat run.txt)"
}

for name in reference serial; do
  [ -x "$bin/sim_time-$name" ] || continue
  run "$name" "$name-kill"
  kill_while_asleep "$pid"
  wait "$pid" 2>/dev/null
  check "$name-kill"

  run "$name" "$name-term"
  kill -TERM "$pid"
  wait "$pid"
  got=$?
  [ "$got" -eq 75 ] || { cat run.txt >&2; fail "$name: SIGTERM gave exit $got, expected 75"; }
  check "$name-term"
done
[ -d reference-kill ] || fail "no program ran"
echo "the .pvd lists every complete frame after SIGKILL and SIGTERM"
