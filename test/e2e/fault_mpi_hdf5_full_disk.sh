# MPI + HDF5 on a full disk (scenes/faults.cpp, mpi program, parallel HDF5):
# the job stops with the cause, and the partial file is gone, as the message
# says, whichever rank saw the failure first. Five tries at 2 and at 3 ranks
# (which rank fails first varies). It mounts a small tmpfs: it needs root,
# and skips (77) without, or without the mpi program.
#   fault_mpi_hdf5_full_disk.sh BIN MPIEXEC
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=${2:-}
program=$bin/faults-mpi
if [ -z "$mpiexec" ] || [ ! -x "$program" ]; then
  echo "mpi hdf5 full disk: no mpi program; skipped"
  exit 77
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "mpi hdf5 full disk: needs root (mount -t tmpfs); skipped"
  exit 77
fi
disk=$work/disk
mkdir "$disk"
cleanup() { mountpoint -q "$disk" && umount "$disk"; rm -rf "$work"; }
trap cleanup EXIT

for ranks in 2 3; do
  for try in 1 2 3 4 5; do
    mountpoint -q "$disk" && umount "$disk"
    mount -t tmpfs -o size=128k tmpfs "$disk" || fail "cannot mount a tmpfs at $disk"
    OMP_NUM_THREADS=1 timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe -np $ranks \
      "$program" none --quiet --steps 20 --output-every 1 --format hdf5 --out "$disk" \
      >out.txt 2>&1
    got=$?
    [ "$got" -ne 0 ] && [ "$got" -ne 124 ] || { cat out.txt >&2; fail "$ranks ranks, try $try: exit $got"; }
    expect_in out.txt "error while writing '$disk/wash.h5': HDF5 could not"
    if grep -q "the partial file was removed" out.txt; then
      [ -z "$(ls -A "$disk")" ] || fail "$ranks ranks, try $try: 'the partial file was removed', but the disk holds: $(ls -A "$disk")"
    else
      expect_in out.txt "could not be removed"
    fi
  done
done
echo "mpi hdf5 full disk: stopped, no partial file left"
