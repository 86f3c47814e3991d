# A small shock test in CI: run a translated scene at a low resolution, score
# its final state against the exact solution (bench/validation/compare.py) and
# check each metric lies in its band. The bands are the values measured at
# this resolution (docs/validation.md) with room for rounding differences
# between machines, and tight enough that a broken scheme falls out of them.
#   shock_small.sh PROGRAM SIDE PROBLEM TIME "COMPARE ARGS" KEY:LO:HI...
. "$(dirname "$0")/../e2e/lib.sh"
program=$1 side=$2 problem=$3 time=$4 compare_args=$5
shift 5
root=$(cd "$(dirname "$0")/../.." && pwd)

OMP_NUM_THREADS=2 OMP_WAIT_POLICY=passive expect_exit 0 "$program" "$side" --quiet --dump state.csv \
  --format hdf5 --out h5
# shellcheck disable=SC2086
/usr/bin/python3 "$root/bench/validation/compare.py" state.csv --problem "$problem" --time "$time" \
  $compare_args >compare.txt || fail "compare.py failed: $(cat compare.txt)"
metrics=$(tail -1 compare.txt)
# The same scores from the last step of the run's HDF5 file (scripts/wash_read.py).
# shellcheck disable=SC2086
/usr/bin/python3 "$root/bench/validation/compare.py" h5/*.h5 --problem "$problem" --time "$time" \
  $compare_args >compare_h5.txt || fail "compare.py on the .h5 failed: $(cat compare_h5.txt)"
[ "$(tail -1 compare_h5.txt)" = "$metrics" ] ||
  fail "the .h5 scores $(tail -1 compare_h5.txt), the dump $metrics"
echo "$(basename "$program") $side^3: $metrics"
for band in "$@"; do
  IFS=: read -r key lo hi <<<"$band"
  value=$(sed -n "s/.*\b$key=\([^ ]*\).*/\1/p" <<<"$metrics")
  [ -n "$value" ] || fail "no $key in: $metrics"
  awk -v v="$value" -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(v >= lo && v <= hi) }' ||
    fail "$key=$value is outside [$lo, $hi]"
done
echo "$problem: every metric in its band"
