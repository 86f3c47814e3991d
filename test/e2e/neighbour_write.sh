# A write to a neighbour (scenes/neighbour_write.cpp) stops the reference
# build at the write, with the translator's NeighbourWrite message: the
# caller's file:line:col, the setter's name as the translator reports it, and
# "neighbours are read-only", exit status 1.
. "$(dirname "$0")/lib.sh"
bin=$1
wash=${2:-} # the translator, where it is built: its locations must be the same
program="$bin/neighbour_write-reference"

expect_exit 1 "$program" cast --quiet
expect_in out.txt "neighbour_write.cpp:20:39: error: 'set_density' writes to a neighbour particle; neighbours are read-only"
expect_exit 1 "$program" copy --quiet
expect_in out.txt "neighbour_write.cpp:23:12: error: 'set_force_scalar' writes to a neighbour particle; neighbours are read-only"
# The translator rejects both writes with the same file:line:col and message.
scene="$(dirname "$0")/scenes/neighbour_write.cpp"
if [[ -n $wash ]]; then
  expect_exit 1 "$wash" --dump-model "$scene"
  cp out.txt translator.txt
  for line in 20:39 23:12; do
    want=$(grep -o "neighbour_write.cpp:$line: error: .*" translator.txt) ||
      fail "the translator reported nothing at $line"
    for how in cast copy; do
      "$program" "$how" --quiet > reference.txt 2>&1 || true
      grep -qF -- "$want" reference.txt && continue 2
    done
    fail "no reference run reported '$want'"
  done
fi
# The same kernel writing only its own particle runs.
expect_exit 0 "$program" none --quiet
echo "neighbour write: ok"
