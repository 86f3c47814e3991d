# Generated code reads a variable with a constant name through a slot bound
# when the run starts (wash/backend/variables.hpp). Where the variable exists,
# the reads see every write (a void kernel's) and the run ends as the
# reference's; where main never added it, the read stops the run with the
# reference's message, at the same file, line and column (the rewrite of the
# particle accesses before the call on its line moves it: generated code
# passes the call's CallSite as written). Not the same path: the reference
# build names the source relative to its build folder.
. "$(dirname "$0")/lib.sh"
bin=$1
shift
backends=("$@")
[ ${#backends[@]} -gt 0 ] || backends=(serial openmp)
scene=variable_unadded

expect_exit 0 "$bin/$scene-reference" add --quiet --dump reference.csv --out ref
expect_exit 1 "$bin/$scene-reference" --quiet --out ref
# "<scene>.cpp:<line>:<column>: error: <message>" from a run's output.
where() {
  sed -n "s|^.*/\($scene\.cpp:[0-9]*:[0-9]*\): \(error: variable 'gain' was never added.*\)$|\1: \2|p" out.txt
}
where >reference-error.txt
[ -s reference-error.txt ] || { cat out.txt >&2; fail "the reference did not stop at the read"; }
for backend in "${backends[@]}"; do
  [ -x "$bin/$scene-$backend" ] || fail "no $bin/$scene-$backend"
  expect_exit 0 "$bin/$scene-$backend" add --quiet --dump "$backend.csv" --out "$backend"
  cmp -s reference.csv "$backend.csv" || fail "$scene-$backend differs from the reference"
  expect_exit 1 "$bin/$scene-$backend" --quiet --out "$backend"
  where >"$backend-error.txt"
  [ -s "$backend-error.txt" ] || { cat out.txt >&2; fail "$scene-$backend did not stop at the read"; }
  cmp -s reference-error.txt "$backend-error.txt" ||
    fail "$scene-$backend: '$(cat "$backend-error.txt")', the reference: '$(cat reference-error.txt)'"
done
echo "variable slots: ${backends[*]} as the reference, with the variable and without"
