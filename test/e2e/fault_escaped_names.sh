# Names are escaped wherever they are written (issue 31): a simulation name
# and a field name holding & < > " ' a comma and a newline give a .pvd and
# .vtp files (binary and ASCII) that XML parsers and VTK's own readers read,
# CSV frames whose header Python's csv module reads, and an HDF5 file whose
# datasets h5py finds, every name exactly as given.
#   fault_escaped_names.sh BIN [MPIEXEC]
. "$(dirname "$0")/lib.sh"
bin=$1
py=/usr/bin/python3
"$py" -c "import vtk, h5py" 2>/dev/null ||
  { echo "SKIP: vtk or h5py (python3-vtk9, python3-h5py) is not installed"; exit 77; }
p=$bin/hostile_names-reference
sim=$'s&<a>"b\'c,d\ne'
field=$'f&<g>"h\'i,j\nk'
for fmt in vtk ascii csv hdf5; do
  case $fmt in
    ascii) args=(--format vtk --vtk-encoding ascii) ;;
    *) args=(--format "$fmt") ;;
  esac
  expect_exit 0 "$p" --quiet --output-every 1 "${args[@]}" --out "$fmt" -- "$sim" "$field"
done

"$py" - "$sim" "$field" <<'PY' || fail "a name did not read back (above)"
import csv, os, sys
import xml.etree.ElementTree as ET
import h5py
import vtk
sim, field = sys.argv[1:]
frames = [f"{sim}_{k:06d}" for k in range(3)]

def fail(msg):
    sys.exit(f"FAIL: {msg}")

for d in ("vtk", "ascii"):
    pvd = os.path.join(d, sim + ".pvd")
    listed = [e.get("file") for e in ET.parse(pvd).getroot().iter("DataSet")]
    if listed != [f + ".vtp" for f in frames]:
        fail(f"{d}: the .pvd lists {listed!r}")
    parser = vtk.vtkXMLDataParser()  # VTK's own XML parser, as its readers use
    parser.SetFileName(pvd)
    if not parser.Parse():
        fail(f"{d}: VTK's XML parser cannot parse the .pvd")
    collection = parser.GetRootElement().GetNestedElement(0)
    files = [collection.GetNestedElement(i).GetAttribute("file")
             for i in range(collection.GetNumberOfNestedElements())]
    if files != listed:
        fail(f"{d}: VTK's XML parser reads {files!r} from the .pvd")
    for k, f in enumerate(listed):
        path = os.path.join(d, f)
        if d == "ascii":
            ET.parse(path)  # well-formed (the binary one is not XML after its header)
        r = vtk.vtkXMLPolyDataReader()
        r.SetFileName(path)
        r.Update()
        data = r.GetOutput().GetPointData()
        names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())]
        if field not in names or field + "_v" not in names:
            fail(f"{path}: point data {names!r}, no {field!r}")
        if k and data.GetArray(field).GetValue(0) % 1 != 0.25:  # neighbours + 0.25
            fail(f"{path}: {field!r} of particle 0 is {data.GetArray(field).GetValue(0)}")

for f in frames:
    with open(os.path.join("csv", f + ".csv"), newline="") as file:
        header = next(csv.reader(file))
    if header[-3:] != [field, field + "_v_x", field + "_v_y"]:
        fail(f"{f}.csv: header {header!r}")

with h5py.File(os.path.join("hdf5", sim + ".h5"), "r") as h5:
    for k in range(3):
        g = h5[f"Step#{k}"]
        if field not in g or (k and g[field][0] % 1 != 0.25) or field + "_v_y" not in g:
            fail(f"Step#{k}: datasets {sorted(g)!r}")
PY
echo "hostile names read back exactly"
