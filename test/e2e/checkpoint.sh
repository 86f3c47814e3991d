# Checkpoint and restart, bit for bit: run a scene straight; run it halfway
# with a checkpoint, restart, run to the end; the final --dump, every frame
# after the restart and the .pvd series must be byte-identical to the straight
# run's. On the reference, serial, OpenMP (checkpoint at 2 and 4 threads,
# restart at 4 and 1) and MPI (checkpoint at 2 ranks, restart at 3 and at 1;
# checkpoint at 3, restart with the OpenMP program), against the serial run.
#   checkpoint.sh BIN MPIEXEC SCENE HALF "WASH OPTIONS" [SIMULATION ARGS...]
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=$2 scene=$3 half=$4 options=$5
shift 5
read -r -a wash <<<"$options"
sim=("$@")
[ ${#sim[@]} -gt 0 ] && sim=(-- "${sim[@]}")

# same STRAIGHT RESTARTED: the dumps, the series and the frames after $half.
same() {
  local a=$1 b=$2 frames=0
  shopt -s nullglob
  cmp -s "$a.csv" "$b.csv" || fail "$scene: --dump of $b differs from $a's: $(cmp "$a.csv" "$b.csv")"
  for f in "$a"/*.pvd "$a"/*_[0-9][0-9][0-9][0-9][0-9][0-9].*; do
    local name=${f##*/} step=${f##*_}
    step=${step%%.*}
    [[ $name == *.pvd ]] || [ $((10#$step)) -gt "$half" ] || continue
    cmp -s "$f" "$b/$name" || fail "$scene: $b/$name differs from the straight run's ($a)"
    frames=$((frames + 1))
  done
  [ "$frames" -ge 2 ] || fail "$scene: only $frames frames after step $half to compare in $a"
}
mpi() { # mpi RANKS ARGS...
  local n=$1
  shift
  OMP_NUM_THREADS=1 expect_exit 0 timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe \
    -np "$n" "$@"
}
halfway=(--steps "$half" --checkpoint-every "$half" --quiet)
again=(--quiet)

# The reference: straight, halfway, restarted from the folder (its newest).
p=$bin/$scene-reference
expect_exit 0 "$p" "${wash[@]}" --quiet --out ref --dump ref.csv "${sim[@]}"
expect_exit 0 "$p" "${wash[@]}" "${halfway[@]}" --out ref-r "${sim[@]}"
expect_exit 0 "$p" "${wash[@]}" "${again[@]}" --out ref-r --dump ref-r.csv --restart ref-r/checkpoints "${sim[@]}"
same ref ref-r

# Serial: a checkpoint every half/2 steps, only the newest kept.
p=$bin/$scene-serial
expect_exit 0 "$p" "${wash[@]}" --quiet --out ser --dump ser.csv "${sim[@]}"
expect_exit 0 "$p" "${wash[@]}" "${halfway[@]}" --checkpoint-every $((half / 2)) --keep-checkpoints 1 \
  --out ser-r "${sim[@]}"
kept=$(ls ser-r/checkpoints | tr '\n' ' ')
[ "$kept" = "$(printf 'checkpoint_%06d ' "$half")" ] || fail "$scene: --keep-checkpoints 1 left: $kept"
expect_exit 0 "$p" "${wash[@]}" "${again[@]}" --out ser-r --dump ser-r.csv --restart ser-r/checkpoints "${sim[@]}"
same ser ser-r

if [ -x "$bin/$scene-openmp" ]; then
  p=$bin/$scene-openmp
  for threads in "2 4" "4 1"; do
    read -r w r <<<"$threads"
    OMP_NUM_THREADS=$w expect_exit 0 "$p" "${wash[@]}" "${halfway[@]}" --out "omp$w" "${sim[@]}"
    OMP_NUM_THREADS=$r expect_exit 0 "$p" "${wash[@]}" "${again[@]}" --out "omp$w" \
      --dump "omp$w.csv" --restart "omp$w/checkpoints" "${sim[@]}"
    same ser "omp$w"
  done
fi

# MPI frames list the particles in the order rank 0 gathered them, which
# depends on the domain: the MPI runs write CSV frames (sorted by id) instead.
if [ -x "$bin/$scene-mpi" ] && [ -n "$mpiexec" ]; then
  expect_exit 0 "$bin/$scene-serial" "${wash[@]}" --quiet --format csv --out csv --dump csv.csv \
    "${sim[@]}"
  p=$bin/$scene-mpi
  halfway+=(--format csv)
  again+=(--format csv)
  ckpt() { printf '%s/checkpoints/checkpoint_%06d' "$1" "$half"; }
  mpi 2 "$p" "${wash[@]}" "${halfway[@]}" --out mpi2 "${sim[@]}"
  [ -f "$(ckpt mpi2)/shard_00001.wck" ] || fail "$scene: no shard of rank 1 in $(ckpt mpi2)"
  for ranks in 3 1; do
    mpi "$ranks" "$p" "${wash[@]}" "${again[@]}" --out "mpi2-$ranks" --dump "mpi2-$ranks.csv" \
      --restart "$(ckpt mpi2)" "${sim[@]}"
    same csv "mpi2-$ranks"
  done
  mpi 3 "$p" "${wash[@]}" "${halfway[@]}" --out mpi3 "${sim[@]}"
  if [ -x "$bin/$scene-openmp" ]; then
    OMP_NUM_THREADS=2 expect_exit 0 "$bin/$scene-openmp" "${wash[@]}" "${again[@]}" --out mpi3 \
      --dump mpi3.csv --restart "$(ckpt mpi3)" "${sim[@]}"
    same csv mpi3
  fi
fi
echo "$scene: restarted runs identical to the straight run after step $half"
