#!/usr/bin/env bash
# handwritten_matches_reference.sh REFERENCE HANDWRITTEN [--size N] [--steps S]
#
# The proof that the performance baseline computes what the seed computes: runs
# the reference build and the hand-written program for S steps (default 200) and
# requires their --dump files to be byte-identical, with the hand-written one
# run at OMP_NUM_THREADS = 1, 2 and 4. With --size N, REFERENCE must be the seed
# scaled to N particles (bench/scenes/make_scaled_seed.sh) and the hand-written
# program runs with --size N. Speed is never checked here.
set -euo pipefail

ref=$1
hw=$2
shift 2
steps=200
size_args=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --size) size_args=(--size "$2"); shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    *) echo "$0: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
for p in "$ref" "$hw"; do
  [[ -x $p ]] || { echo "FAIL: '$p' is not an executable" >&2; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$ref" --steps "$steps" --quiet --out "$work/out-ref" --dump "$work/reference.csv" >/dev/null
[[ -s $work/reference.csv ]] || { echo "FAIL: the reference wrote no dump" >&2; exit 1; }
rows=$(($(wc -l < "$work/reference.csv") - 1))
echo "reference: $rows particles, $steps steps"

status=0
for threads in 1 2 4; do
  dump=$work/handwritten-$threads.csv
  OMP_NUM_THREADS=$threads "$hw" "${size_args[@]}" --steps "$steps" --quiet \
    --out "$work/out-hw-$threads" --dump "$dump" >/dev/null
  if cmp -s "$work/reference.csv" "$dump"; then
    echo "ok: OMP_NUM_THREADS=$threads: byte-identical dump"
  else
    echo "FAIL: OMP_NUM_THREADS=$threads: the dump differs from the reference's:" >&2
    cmp "$work/reference.csv" "$dump" >&2 || true
    diff "$work/reference.csv" "$dump" | head -n 6 >&2 || true
    status=1
  fi
done
# The final frame (VTK, the default format) must match as well.
if ! diff -r "$work/out-ref" "$work/out-hw-2" >/dev/null; then
  echo "FAIL: the output directories differ:" >&2
  diff -rq "$work/out-ref" "$work/out-hw-2" >&2 || true
  status=1
else
  echo "ok: output directory (final VTK frame) identical"
fi
exit $status
