# Helpers for the end-to-end scripts: fail loudly, with what was expected.
set -u
fail() { echo "FAIL: $*" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# csv_range FILE COLUMN: prints "min max" of a column, found by header name.
csv_range() {
  awk -F, -v col="$2" 'NR==1 { for (i = 1; i <= NF; i++) if ($i == col) c = i; if (!c) exit 2; next }
    { v = $c + 0; if (NR == 2 || v < lo) lo = v; if (NR == 2 || v > hi) hi = v }
    END { printf "%.17g %.17g\n", lo, hi }' "$1" || fail "no column $2 in $1"
}

# expect_exit CODE CMD...: runs CMD with output in out.txt, checks its exit status.
expect_exit() {
  local want=$1; shift
  "$@" >out.txt 2>&1
  local got=$?
  [ "$got" -eq "$want" ] || { cat out.txt >&2; fail "'$*' exited $got, expected $want"; }
}

# expect_in FILE TEXT: FILE contains TEXT.
expect_in() { grep -qF -- "$2" "$1" || { cat "$1" >&2; fail "'$2' not in $1"; }; }

# kill_while_asleep PID: SIGKILL PID while its one thread sleeps in the kernel
# (clock_nanosleep or nanosleep, the scenes' slow kernels), never mid-write:
# a kill test then checks what a kill leaves, not a torn write. Stops it and
# looks, up to 500 times, then kills it anyway.
kill_while_asleep() {
  local call
  for _ in $(seq 500); do
    kill -STOP "$1"
    read -r call _ <"/proc/$1/syscall" && { [ "$call" = 230 ] || [ "$call" = 35 ]; } && break
    kill -CONT "$1"
    sleep 0.003
  done
  kill -KILL "$1"
}
