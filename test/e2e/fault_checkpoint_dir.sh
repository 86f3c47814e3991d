# An unusable --checkpoint-dir is refused before step 1, not at the first
# checkpoint after an interval's work (scenes/faults.cpp): one that cannot be
# created (/proc/x, under a file), on the reference and an MPI job, with
# checkpoints asked for or only the folder named (a signal writes one there).
#   fault_checkpoint_dir.sh BIN [MPIEXEC]
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=${2:-}
program=$bin/faults-reference
touch afile

# refused WANT RUN...: exit 1 within the bound, the reason, no frame written.
refused() {
  local want=$1
  shift
  rm -rf out
  timeout 60 "$@" none --steps 100000000 --output-every 1 --out out >out.txt 2>&1
  local got=$?
  [ "$got" -ne 124 ] || fail "not refused before the run: $*"
  [ "$got" -ne 0 ] || fail "an unusable checkpoint folder was accepted: $*"
  expect_in out.txt "$want"
  [ -z "$(ls -A out 2>/dev/null)" ] || fail "frames written before the refusal: $(ls -A out | head)"
}
for dir in /proc/x afile/ck; do
  refused "error: cannot create checkpoint directory '$dir'" \
    "$program" --checkpoint-every 1000000 --checkpoint-dir "$dir"
  refused "error: cannot create checkpoint directory '$dir'" "$program" --checkpoint-dir "$dir"
done
# The default (<out>/checkpoints) under an --out that cannot hold it.
mkdir -p blocked && touch blocked/checkpoints
timeout 60 "$program" none --steps 100000000 --checkpoint-every 1000000 --out blocked >out.txt 2>&1
[ $? -eq 1 ] || { cat out.txt >&2; fail "a file in the way of <out>/checkpoints was not refused at start"; }
expect_in out.txt "error: cannot create checkpoint directory 'blocked/checkpoints'"
# No checkpoint asked for, no folder named: no checkpoints folder is made.
expect_exit 0 "$program" none --steps 2 --out plain
[ ! -e plain/checkpoints ] || fail "a run without checkpoints made plain/checkpoints"
if [ -n "$mpiexec" ] && [ -x "$bin/faults-mpi" ]; then
  refused "error: cannot create checkpoint directory '/proc/x'" \
    env OMP_NUM_THREADS=1 "$mpiexec" --allow-run-as-root --oversubscribe -np 2 "$bin/faults-mpi" \
    --checkpoint-every 1000000 --checkpoint-dir /proc/x
fi
echo "checkpoint dir: refused before step 1"
