# Output faults (scenes/faults.cpp, reference build): a frame that fails on a
# full disk leaves no truncated file, a run that cannot write stops before
# its first step, and output names stay inside --out. The full-disk checks
# mount small tmpfs file systems, so they need root: without it the test
# reports itself skipped (77), never passed.
. "$(dirname "$0")/lib.sh"
bin=$1
program="$bin/faults-reference"
# A run that would take days: finishing fast means it stopped at start-up.
endless="--steps 1000000000"

# An unusable --dump path is found at start-up, not after the last step.
timeout 60 "$program" none --quiet $endless --dump no/such/dir/dump.csv >out.txt 2>&1
[ $? -eq 1 ] || { cat out.txt >&2; fail "a --dump into a missing directory was not refused at start-up"; }
expect_in out.txt "error: cannot write the dump to 'no/such/dir/dump.csv': No such file or directory"
mkdir adir
timeout 60 "$program" none --quiet $endless --dump adir >out.txt 2>&1
[ $? -eq 1 ] || { cat out.txt >&2; fail "a --dump onto a directory was not refused at start-up"; }
expect_in out.txt "error: cannot write the dump to 'adir': it is a directory"

# Simulation names cannot lead out of --out (refused at set-up, nothing written).
mkdir -p names/out
for name in ../escaped /tmp/wash-escaped-$$ sub/name; do
  expect_exit 1 "$program" none 400 "$name" --quiet --steps 1 --out names/out
  expect_in out.txt "error: output file name '$name' is not a plain file name"
done
[ -z "$(ls -A names/out)" ] && [ "$(ls names)" = out ] || fail "a refused name wrote files: $(find names)"
ls /tmp/wash-escaped-$$* >/dev/null 2>&1 && { rm -f /tmp/wash-escaped-$$*; fail "a name escaped to /tmp"; }
# A dump to a device is written in place (no temporary file beside it).
expect_exit 1 "$program" none --quiet --steps 1 --out devout --dump /dev/full
expect_in out.txt "error: error while writing '/dev/full': No space left on device"
expect_exit 0 "$program" none --quiet --steps 1 --out devout --dump /dev/null

if [ "$(id -u)" -ne 0 ]; then
  echo "output faults: full-disk checks need root (mount -t tmpfs); skipped"
  exit 77
fi
disk=$work/disk
mkdir "$disk"
cleanup() { mountpoint -q "$disk" && umount "$disk"; rm -rf "$work"; }
trap cleanup EXIT
mount_disk() { # mount_disk SIZE: an empty tmpfs of SIZE at $disk
  mountpoint -q "$disk" && umount "$disk"
  mount -t tmpfs -o size="$1" tmpfs "$disk" || fail "cannot mount a tmpfs at $disk"
}

# The disk fills during the run: the frame that does not fit is not left
# behind truncated, every frame there is whole, the run stops with exit 1.
for format in vtk csv; do
  mount_disk 128k
  expect_exit 1 "$program" none --quiet --steps 20 --output-every 1 --format $format --out "$disk"
  expect_in out.txt "No space left on device"
  ls "$disk"/wash_000000.* >/dev/null 2>&1 || fail "$format: no frame was written before the disk was full"
  for frame in "$disk"/wash_*; do
    case $format in
    vtk) [ "$(tail -n 1 "$frame")" = "</VTKFile>" ] || fail "truncated frame $frame left behind" ;;
    csv) [ "$(wc -l <"$frame")" -eq 401 ] && [ -z "$(tail -c 1 "$frame")" ] ||
           fail "truncated frame $frame left behind" ;;
    esac
  done
  ls -A "$disk" | grep -q "partial" && fail "$format: a partial file was left: $(ls -A "$disk")"
done

# HDF5: the step that does not fit stops the run, and the run's one file,
# which that step left unreadable, is removed (partial files are never left).
mount_disk 128k
expect_exit 1 "$program" none --quiet --steps 20 --output-every 1 --format hdf5 --out "$disk"
expect_in out.txt "error: error while writing '$disk/wash.h5': HDF5 could not"
expect_in out.txt "No space left on device"
[ -z "$(ls -A "$disk")" ] || fail "hdf5: files left on the full disk: $(ls -A "$disk")"

# A disk already full at start: the run stops before its first step, for
# the frames' directory and for the --dump file.
mount_disk 64k
dd if=/dev/zero of="$disk/filler" bs=4k count=64 >/dev/null 2>&1
timeout 60 "$program" none --quiet $endless --out "$disk/out" >out.txt 2>&1
[ $? -eq 1 ] || { cat out.txt >&2; fail "a full disk for frames was not refused at start-up"; }
expect_in out.txt "error: cannot write frames to '$disk/out': reserving"
expect_in out.txt "No space left on device"
timeout 60 "$program" none --quiet $endless --out frames --dump "$disk/dump.csv" >out.txt 2>&1
[ $? -eq 1 ] || { cat out.txt >&2; fail "a full disk for the dump was not refused at start-up"; }
expect_in out.txt "error: cannot write the dump to '$disk/dump.csv': reserving"
ls -A "$disk" "$disk/out" | grep -q "partial\|write-test" && fail "a probe file was left on the disk"
echo "output faults: ok"
