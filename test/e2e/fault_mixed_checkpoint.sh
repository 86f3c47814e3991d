# A checkpoint's index names its shards' checksums: the index of one
# checkpoint with a shard of another (of the same run, or of another run at
# the same iteration) is refused, nothing written, on the reference, a
# generated program and an MPI job (scenes/faults.cpp; its update kernel
# changes every particle's density each step).
#   fault_mixed_checkpoint.sh BIN [MPIEXEC]
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=${2:-}
want="is not the one its index was written with (files of different checkpoints are mixed)"

# refused RESTART-COMMAND...: exit 1 with $want, nothing written.
refused() {
  rm -rf refused refused.csv
  "$@" --steps 30 --quiet --out refused --dump refused.csv >out.txt 2>&1
  local got=$?
  [ "$got" -ne 0 ] || fail "a mixed checkpoint was restarted: $*"
  expect_in out.txt "$want"
  [ ! -e refused.csv ] && [ -z "$(ls refused 2>/dev/null)" ] || fail "a refused restart wrote: $(ls refused)"
}
# mixed INDEX-OF SHARDS-OF K...: a checkpoint with the index of one and shards K of another.
mixed() {
  local index=$1 shards=$2
  shift 2
  rm -rf mixed && cp -r "$index" mixed
  for k in "$@"; do cp "$shards/shard_0000$k.wck" mixed/; done
}

for build in reference serial; do
  p=$bin/faults-$build
  [ -x "$p" ] || continue
  rm -rf run other
  expect_exit 0 "$p" none --steps 20 --checkpoint-every 10 --quiet --out run
  c=run/checkpoints
  mixed $c/checkpoint_000020 $c/checkpoint_000010 0
  refused "$p" none --restart mixed
  mixed $c/checkpoint_000010 $c/checkpoint_000020 0
  refused "$p" none --restart mixed
  # A shard of another run (300 particles) at the same iteration.
  expect_exit 0 "$p" none 300 --steps 10 --checkpoint-every 10 --quiet --out other
  mixed $c/checkpoint_000010 other/checkpoints/checkpoint_000010 0
  refused "$p" none --restart mixed
  # The unmixed checkpoints still restart.
  expect_exit 0 "$p" none --steps 30 --quiet --out good --restart $c/checkpoint_000010
done

# MPI: the shard of one rank from another checkpoint, restarted on 2 ranks
# and on 1 (the serial program reads both shards).
if [ -n "$mpiexec" ] && [ -x "$bin/faults-mpi" ]; then
  mpi() {
    OMP_NUM_THREADS=1 timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe -np 2 \
      "$bin/faults-mpi" none "$@"
  }
  mpi --steps 20 --checkpoint-every 10 --quiet --out mrun >out.txt 2>&1 ||
    { cat out.txt >&2; fail "the 2-rank run failed"; }
  c=mrun/checkpoints
  [ -f $c/checkpoint_000020/shard_00001.wck ] || fail "no 2-rank checkpoint: $(ls $c)"
  mixed $c/checkpoint_000020 $c/checkpoint_000010 1
  refused mpi --restart mixed
  [ -x "$bin/faults-serial" ] && refused "$bin/faults-serial" none --restart mixed
  mpi --steps 30 --quiet --out mgood --restart $c/checkpoint_000010 >out.txt 2>&1 ||
    { cat out.txt >&2; fail "the unmixed 2-rank checkpoint did not restart"; }
fi
echo "mixed checkpoints: refused"
