# A restart into the same --out continues every output series (issue 31):
# a run of 24 steps with checkpoints, restarted from its checkpoint at 12 into
# the same folder, leaves the files of the straight run: every HDF5 step (read
# by h5py, Step#k numbering continued, not started again at Step#0), every VTK
# frame and the .pvd, every CSV frame. A restart to 18 drops the steps past
# it; after SIGTERM the HDF5 file holds the steps so far and a restart
# continues it, after SIGKILL the restart continues the partial file; an .h5
# of another run is refused and left as it was. On the
# reference, the serial program and the mpi one at 2 ranks (parallel HDF5).
#   fault_restart_series.sh BIN MPIEXEC
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=${2:-}
py=/usr/bin/python3
"$py" -c "import h5py" 2>/dev/null || { echo "SKIP: h5py (python3-h5py) is not installed"; exit 77; }

# same_h5 A B: the same groups, attributes and datasets, bit for bit.
same_h5() {
  "$py" - "$1" "$2" <<'PY' || fail "$2 is not the straight run's $1 (above)"
import sys
import h5py
import numpy as np
a, b = (h5py.File(p, "r") for p in sys.argv[1:])
if sorted(a) != sorted(b):
    sys.exit(f"groups {sorted(b)}, expected {sorted(a)}")
for name in a:
    for key in ("step", "time", "particle_count"):
        if a[name].attrs[key] != b[name].attrs[key]:
            sys.exit(f"{name}: {key} {b[name].attrs[key]}, expected {a[name].attrs[key]}")
    if sorted(a[name]) != sorted(b[name]):
        sys.exit(f"{name}: datasets {sorted(b[name])}, expected {sorted(a[name])}")
    for d in a[name]:
        x, y = a[name][d][()], b[name][d][()]
        if x.dtype != y.dtype or x.tobytes() != y.tobytes():
            sys.exit(f"{name}/{d} differs")
PY
}
# same_frames A B: every frame file and .pvd of A is in B, byte for byte.
same_frames() {
  local f n=0
  for f in "$1"/*.vtp "$1"/*.csv "$1"/*.pvd; do
    [ -e "$f" ] || continue
    cmp -s "$f" "$2/${f##*/}" || fail "$2/${f##*/} is not the straight run's $f"
    n=$((n + 1))
  done
  [ "$n" -ge 7 ] || fail "only $n frames in $1"
}

opts=(--steps 24 --output-every 3 --quiet)
runs=(reference serial)
[ -n "$mpiexec" ] && [ -x "$bin/sim_time-mpi" ] && runs+=(mpi)
for name in "${runs[@]}"; do
  [ -x "$bin/sim_time-$name" ] || continue
  p=("$bin/sim_time-$name")
  [ "$name" = mpi ] && p=(env OMP_NUM_THREADS=1 "$mpiexec" --allow-run-as-root --oversubscribe -np 2 "${p[@]}")
  formats=(hdf5 vtk csv)
  [ "$name" = mpi ] && formats=(hdf5)
  for fmt in "${formats[@]}"; do
    d=$name-$fmt
    expect_exit 0 timeout 120 "${p[@]}" "${opts[@]}" --format "$fmt" --out "$d-straight"
    expect_exit 0 timeout 120 "${p[@]}" "${opts[@]}" --steps 18 --format "$fmt" --out "$d-18"
    expect_exit 0 timeout 120 "${p[@]}" "${opts[@]}" --format "$fmt" --checkpoint-every 12 --out "$d"
    cp -r "$d" "$d-to18"
    expect_exit 0 timeout 120 "${p[@]}" "${opts[@]}" --format "$fmt" --out "$d" \
      --restart "$d/checkpoints/checkpoint_000012"
    expect_exit 0 timeout 120 "${p[@]}" "${opts[@]}" --steps 18 --format "$fmt" --out "$d-to18" \
      --restart "$d-to18/checkpoints/checkpoint_000012"
    if [ "$fmt" = hdf5 ]; then
      same_h5 "$d-straight/sim_time.h5" "$d/sim_time.h5"
      same_h5 "$d-18/sim_time.h5" "$d-to18/sim_time.h5"
    else
      same_frames "$d-straight" "$d"
      same_frames "$d-18" "$d-to18"
    fi
  done

  # SIGTERM: a checkpoint, exit 75, and the HDF5 file of the steps so far,
  # which a restart continues to the straight run's file.
  slow=(inf slow --end-time 1e9 --output-every 3 --quiet --format hdf5)
  "${p[@]}" "${slow[@]}" --steps 100000 --out "$name-term" >term.txt 2>&1 &
  pid=$!
  for _ in $(seq 200); do grep -q "first step done" term.txt && break; sleep 0.05; done
  sleep 0.3
  target=$pid
  [ "$name" = mpi ] && target=$(pgrep -f -n "sim_time-mpi inf slow .* --out $name-term" | grep -v "^$pid$")
  [ -n "$target" ] || fail "$name: no process to signal"
  kill -TERM "$target" # under MPI one rank: every rank stops after the same iteration
  wait "$pid"
  got=$?
  [ "$got" -eq 75 ] || { cat term.txt >&2; fail "$name: SIGTERM gave exit $got, expected 75"; }
  [ -f "$name-term/sim_time.h5" ] || fail "$name: no sim_time.h5 after SIGTERM: $(ls "$name-term")"
  k=$(ls "$name-term/checkpoints" | tail -1)
  k=$((10#${k#checkpoint_}))
  expect_exit 0 timeout 120 "${p[@]}" "${slow[@]}" --steps $((k + 7)) --out "$name-term" \
    --restart "$name-term/checkpoints"
  expect_exit 0 timeout 120 "${p[@]}" "${slow[@]}" --steps $((k + 7)) --out "$name-term-straight"
  same_h5 "$name-term-straight/sim_time.h5" "$name-term/sim_time.h5"

  # SIGKILL (while the run sleeps in a kernel, not mid-write): only the
  # partial file is left, and the restart continues it in place.
  if [ "$name" != mpi ]; then
    "${p[@]}" "${slow[@]}" --steps 100000 --checkpoint-every 5 --out "$name-kill" >kill.txt 2>&1 &
    pid=$!
    for _ in $(seq 200); do
      [ "$(ls "$name-kill/checkpoints" 2>/dev/null | grep -vc partial)" -ge 2 ] && break
      sleep 0.05
    done
    kill_while_asleep "$pid"
    wait "$pid" 2>/dev/null
    [ ! -e "$name-kill/sim_time.h5" ] || fail "$name: a killed run left sim_time.h5"
    k=$(ls "$name-kill/checkpoints" | grep -v partial | tail -1)
    k=$((10#${k#checkpoint_}))
    expect_exit 0 timeout 120 "${p[@]}" "${slow[@]}" --steps $((k + 7)) --out "$name-kill" \
      --restart "$name-kill/checkpoints"
    expect_exit 0 timeout 120 "${p[@]}" "${slow[@]}" --steps $((k + 7)) --out "$name-kill-straight"
    same_h5 "$name-kill-straight/sim_time.h5" "$name-kill/sim_time.h5"
  fi
  echo "$name: every series continued"
done
[ -d reference-hdf5 ] || fail "no program ran"

# An .h5 that is not the checkpoint's series (frames every 4 steps, not 3):
# refused before any step, the file unchanged.
p=$bin/sim_time-reference
cp reference-hdf5/sim_time.h5 every4.h5
expect_exit 0 "$p" "${opts[@]}" --output-every 4 --format hdf5 --out other
cp other/sim_time.h5 reference-hdf5/sim_time.h5
sum=$(md5sum <reference-hdf5/sim_time.h5)
expect_exit 1 "$p" "${opts[@]}" --format hdf5 --out reference-hdf5 \
  --restart reference-hdf5/checkpoints/checkpoint_000012
expect_in out.txt "cannot continue 'reference-hdf5/sim_time.h5' after the checkpoint: its Step#1"
[ "$(md5sum <reference-hdf5/sim_time.h5)" = "$sum" ] || fail "the refused .h5 was changed"
ls reference-hdf5 | grep -q partial && fail "a refused restart left $(ls reference-hdf5)"
echo "restarts continue every series"
