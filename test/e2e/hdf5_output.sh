# --format hdf5 read back by h5py (Debian python3-h5py): every Step#k group of
# the run's one .h5 file, every dataset and the time, step and particle_count
# attributes, against the CSV frames and the --dump of the same run, value for
# value (the CSV files hold %.17g, which reads back as the same double), on
# every backend given, the mpi one at 2 and 3 ranks (parallel HDF5, each rank
# writing its own rows); the values are also those of the reference's file.
#   hdf5_output.sh BIN MPIEXEC SCENE 'RUN ARGS' BACKEND...
# SCENE: a program BIN/SCENE-<backend> per backend, BIN/SCENE-reference too.
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=$2 scene=$3 args=$4
shift 4
py=/usr/bin/python3
"$py" -c "import h5py" 2>/dev/null || { echo "SKIP: h5py (python3-h5py) is not installed"; exit 77; }
read -r -a run_args <<<"$args"

runs=(reference)
for backend in "$@"; do
  if [ "$backend" = mpi ]; then
    [ -n "$mpiexec" ] || fail "no mpiexec for the mpi backend"
    runs+=(mpi2 mpi3)
  else
    runs+=("$backend")
  fi
done
for name in "${runs[@]}"; do
  threads=2
  case $name in
    mpi[0-9]) run=("$mpiexec" --allow-run-as-root --oversubscribe -np "${name#mpi}" "$bin/$scene-mpi")
      threads=1 ;; # ranks enough for the test's two cores
    *) run=("$bin/$scene-$name") ;;
  esac
  OMP_NUM_THREADS=$threads expect_exit 0 timeout 120 "${run[@]}" "${run_args[@]}" --quiet --format hdf5 \
    --out "$name.h5out" --dump "$name.dump.csv"
  OMP_NUM_THREADS=$threads expect_exit 0 timeout 120 "${run[@]}" "${run_args[@]}" --quiet --format csv \
    --out "$name.csvout"
  [ "$(ls "$name.h5out")" = "$scene.h5" ] || fail "$name wrote $(ls "$name.h5out"), expected only $scene.h5"
done

"$py" - "$scene" "${runs[@]}" <<'PY' || fail "h5py disagrees (above)"
import csv, glob, os, sys
import h5py
import numpy as np

scene, runs = sys.argv[1], sys.argv[2:]

def fail(msg):
    print("FAIL:", msg, file=sys.stderr)
    sys.exit(1)

def rows(path):
    return {int(r["id"]): r for r in csv.DictReader(open(path))}

def check_step(where, group, table):
    """Every dataset of the group equals the CSV table's column of that name, row by id."""
    ids = group["id"][()]
    if list(ids) != sorted(table):
        fail(f"{where}: ids {list(ids)[:5]}... are not the CSV's ids in ascending order")
    for column in next(iter(table.values())):
        if column == "id":
            continue
        if column not in group:
            fail(f"{where}: no dataset {column} (it has {sorted(group)})")
        got = group[column][()]
        want = np.array([float(table[i][column]) for i in ids])
        if got.dtype != np.float64 or not np.array_equal(got.view(np.uint64), want.view(np.uint64)):
            k = int(np.flatnonzero(got != want)[0]) if got.shape == want.shape else 0
            fail(f"{where}/{column}: particle {ids[k]} holds {got[k]!r}, the CSV {want[k]!r}")

reference = None
for run in runs:
    path = os.path.join(f"{run}.h5out", f"{scene}.h5")
    f = h5py.File(path, "r")
    frames = sorted(glob.glob(os.path.join(f"{run}.csvout", "*.csv")))
    names = [f"Step#{k}" for k in range(len(frames))]
    if sorted(f.keys()) != sorted(names):
        fail(f"{path}: groups {sorted(f.keys())}, expected {names} (one per CSV frame)")
    previous = -1
    for k, frame in enumerate(frames):
        g = f[f"Step#{k}"]
        table = rows(frame)
        step = int(frame[-10:-4])
        if int(g.attrs["step"]) != step or step <= previous:
            fail(f"{path}/Step#{k}: step attribute {g.attrs['step']}, the CSV frame is step {step}")
        previous = step
        if int(g.attrs["particle_count"]) != len(table) or len(g["id"]) != len(table):
            fail(f"{path}/Step#{k}: particle_count {g.attrs['particle_count']}, {len(table)} rows")
        time = float(g.attrs["time"])
        if "time" in g and not (g["time"][()] == time).all():
            fail(f"{path}/Step#{k}: time attribute {time}, the particles' time {g['time'][0]}")
        for axis in "xyz":
            if axis not in g:
                fail(f"{path}/Step#{k}: no dataset {axis} (H5Part readers need x, y and z)")
        if "z" not in next(iter(table.values())) and (g["z"][()] != 0).any():
            fail(f"{path}/Step#{k}: a 2D run's z is not zero")
        check_step(f"{path}/Step#{k}", g, table)
        if reference is not None:
            r = reference[f"Step#{k}"]
            for d in r:
                if not np.array_equal(r[d][()], g[d][()]):
                    fail(f"{path}/Step#{k}/{d} differs from the reference's")
            if dict(r.attrs) != dict(g.attrs):
                fail(f"{path}/Step#{k}: attributes {dict(g.attrs)}, the reference's {dict(r.attrs)}")
    # The last step is the final state: the --dump, bit for bit.
    check_step(f"{path}/Step#{len(frames) - 1} against the dump", f[f"Step#{len(frames) - 1}"],
               rows(f"{run}.dump.csv"))
    if reference is None:
        reference = f
    print(f"{run}: {len(frames)} steps, {len(f['Step#0'])} datasets each, equal to CSV and dump")
PY
echo "hdf5_output: $scene: ${runs[*]} read back by h5py, equal to the CSV frames and the dump"
