# Helpers for the stability scripts, on top of test/e2e/lib.sh (fail,
# expect_exit, expect_in, csv_range; it also moves into a fresh work directory).
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here/../e2e/lib.sh"

# The OpenMP programs use the caller's thread count, else 2; waiting threads
# sleep instead of spinning, so a run stays fast on a machine busy with other jobs.
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}

# field KEY LINE: the value of KEY in a line of key=value pairs.
field() {
  local v
  v=$(tr ' ' '\n' <<<"$2" | sed -n "s/^$1=//p")
  [ -n "$v" ] || fail "no $1 in: $2"
  echo "$v"
}

# at_most NAME VALUE BOUND: VALUE <= BOUND, numerically, or fail naming both.
at_most() {
  awk -v v="$2" -v b="$3" 'BEGIN { exit !(v + 0 <= b + 0) }' || fail "$1 = $2 exceeds its bound $3"
}

# drift LOG: the drift summary line of a closed_box log (drift.awk).
drift() { awk -f "$here/drift.awk" "$1" || fail "malformed step lines in $1"; }
