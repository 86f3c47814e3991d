# A write to a neighbour (scenes/neighbour_write.cpp) stops the reference
# build at the write, with the translator's NeighbourWrite message: the
# caller's file:line:col (g++ places a call at its opening parenthesis) and
# "neighbours are read-only", exit status 1.
. "$(dirname "$0")/lib.sh"
bin=$1
program="$bin/neighbour_write-reference"

expect_exit 1 "$program" cast --quiet
expect_in out.txt "neighbour_write.cpp:20:50: error: 'set_density' writes to a neighbour particle; neighbours are read-only"
expect_exit 1 "$program" copy --quiet
expect_in out.txt "neighbour_write.cpp:23:28: error: 'set_force_scalar' writes to a neighbour particle; neighbours are read-only"
# The same kernel writing only its own particle runs.
expect_exit 0 "$program" none --quiet
echo "neighbour write: ok"
