# VTK output read back by VTK's own Python reader (Debian python3-vtk9): the
# .pvd series lists every frame at its simulated time, each binary (default)
# or ASCII .vtp has the right points, fields and TimeValue, the values equal
# the CSV frames of the same run exactly, --fields chooses the point data,
# acc is in frames but never in --dump.
#   vtk_output.sh PROGRAM [LAUNCHER...]   (the sim_time scene, any backend;
#   LAUNCHER: e.g. mpiexec -np 3 for the mpi one, whose rank 0 writes chunks)
. "$(dirname "$0")/lib.sh"
program=$1
shift
launcher=("$@")
py=/usr/bin/python3
"$py" -c "import vtk" 2>/dev/null || { echo "SKIP: VTK's Python module (python3-vtk9) is not installed"; exit 77; }

run=(timeout 120 "${launcher[@]}" "$program" --end-time 0.3 --output-dt 0.1 --quiet)
expect_exit 0 "${run[@]}" --out binary --dump dump.csv
expect_exit 0 "${run[@]}" --out ascii --vtk-encoding ascii
expect_exit 0 "${run[@]}" --out csv --format csv
expect_exit 0 "${run[@]}" --out some --fields time,acc
grep -q 'format="appended"' binary/sim_time_000000.vtp || fail "the default VTK frame is not binary"
grep -q 'format="appended"' ascii/sim_time_000000.vtp && fail "--vtk-encoding ascii wrote binary arrays"
head -1 dump.csv | grep -q acc && fail "--dump holds acc: $(head -1 dump.csv)"

"$py" - <<'PY' || fail "VTK's reader disagrees (above)"
import csv, glob, os, sys
import xml.etree.ElementTree as ET
import vtk
from vtk.util.numpy_support import vtk_to_numpy

def fail(msg):
    print("FAIL:", msg, file=sys.stderr)
    sys.exit(1)

def read(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    if r.GetErrorCode():
        fail(f"{path}: reader error {r.GetErrorCode()}")
    return r.GetOutput()

everything = {"id", "vel", "acc", "density", "mass", "smoothing_length", "start", "time", "dt"}
for folder, fields in (("binary", everything), ("ascii", everything), ("some", {"id", "time", "acc"})):
    series = ET.parse(os.path.join(folder, "sim_time.pvd")).getroot().find("Collection")
    listed = [(float(d.get("timestep")), d.get("file")) for d in series]
    files = sorted(os.path.basename(f) for f in glob.glob(os.path.join(folder, "*.vtp")))
    if [f for _, f in listed] != files:
        fail(f"{folder}: the series lists {listed}, the folder has {files}")
    if len(files) < 4:
        fail(f"{folder}: {len(files)} frames, expected 0, 0.1, 0.2 and 0.3")
    for timestep, name in listed:
        data = read(os.path.join(folder, name))
        if data.GetNumberOfPoints() != 64:
            fail(f"{folder}/{name}: {data.GetNumberOfPoints()} points")
        pd = data.GetPointData()
        names = {pd.GetArrayName(k) for k in range(pd.GetNumberOfArrays())}
        if names != fields:
            fail(f"{folder}/{name}: point data {sorted(names)}, expected {sorted(fields)}")
        tv = data.GetFieldData().GetArray("TimeValue")
        if tv is None or tv.GetValue(0) != timestep:
            fail(f"{folder}/{name}: TimeValue {tv and tv.GetValue(0)} but the series says {timestep}")
        # The values, exactly: the CSV frame of the same step.
        rows = {int(r["id"]): r for r in csv.DictReader(open(os.path.join("csv", name[:-4] + ".csv")))}
        ids = vtk_to_numpy(pd.GetArray("id"))
        points = vtk_to_numpy(data.GetPoints().GetData())
        time = vtk_to_numpy(pd.GetArray("time"))
        acc = vtk_to_numpy(pd.GetArray("acc"))
        for k, i in enumerate(ids):
            r = rows[int(i)]
            want = (float(r["x"]), float(r["y"]), 0.0, float(r["time"]), float(r["acc_x"]), float(r["acc_y"]))
            got = (points[k][0], points[k][1], points[k][2], time[k], acc[k][0], acc[k][1])
            if tuple(map(float, got)) != want:
                fail(f"{folder}/{name}: particle {i} reads {got}, the CSV frame has {want}")
        if time[0] != timestep:
            fail(f"{folder}/{name}: particles' time {time[0]} is not the frame's {timestep}")
print("vtk ok")
PY
expect_exit 1 "${run[@]}" --out bad --fields time,nonsense
expect_in out.txt "--fields names 'nonsense', which is no field of this simulation"
echo "vtk_output: series, binary and ASCII frames, --fields and TimeValue read back by VTK"
