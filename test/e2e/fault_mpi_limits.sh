# What the MPI backend cannot run that the reference runs, and what it must
# run as the others do (issue 31, item 16), on test/e2e/scenes/limits_scene.cpp:
#  - a particle created far outside a periodic box (it wraps in) runs, with
#    the serial program's results;
#  - one created far outside a box that is not periodic is refused with a
#    message that names the limit and what to change (the reference runs it);
#  - a search radius of 1e-9 over [0, 1] is refused likewise on every backend;
#  - a NaN position at init is reported as on every other backend.
#   fault_mpi_limits.sh MPIEXEC BIN
. "$(dirname "$0")/lib.sh"
mpiexec=$1 bin=$2
mpi() { OMP_NUM_THREADS=1 timeout -k 5 120 "$mpiexec" --allow-run-as-root --oversubscribe -np "$@"; }
scene=$bin/limits_scene

# 1. Far outside a periodic box: the same as serial at 2 and 3 ranks.
expect_exit 0 timeout -k 5 60 "$scene-reference" far --steps 5 --quiet --out ref --dump far-ref.csv
expect_exit 0 timeout -k 5 60 "$scene-serial" far --steps 5 --quiet --out serial --dump far-serial.csv
cmp -s far-ref.csv far-serial.csv || fail "serial differs from the reference on 'far'"
for n in 2 3; do
  expect_exit 0 mpi "$n" "$scene-mpi" far --steps 5 --quiet --out mpi --dump "far-mpi$n.csv"
  cmp -s far-serial.csv "far-mpi$n.csv" || fail "mpi at $n ranks differs from serial on 'far'"
done

# 2. Far outside a box that is not periodic: beyond the MPI domain's 2^19
# cells, said so, with what to change.
expect_exit 0 timeout -k 5 60 "$scene-reference" far-open --steps 5 --quiet --out ref
expect_exit 1 mpi 2 "$scene-mpi" far-open --steps 5 --quiet --out mpi
expect_in out.txt "error: wash mpi: a particle is in cell 333333"
expect_in out.txt "the MPI backend indexes 2^21 cells per axis, from 2^19 below that one to 3 x 2^19 above it"
expect_in out.txt "keep the particles within 2^19 cells of one another (or inside a periodic box), or use a larger influence radius"

# 3. A radius of 1e-9 over [0, 1]: more cells than a cell grid can index.
expect_exit 1 timeout -k 5 60 "$scene-serial" tiny --steps 2 --quiet --out serial
expect_in out.txt "error: wash: the particles span 5.6"
expect_in out.txt "cells 1.0000000000000001e-09 wide (from the lowest particle to the highest on each axis), more than the 4294967295 a backend's cell grid can index"
expect_in out.txt "use a larger influence radius or smoothing length"
expect_exit 1 mpi 2 "$scene-mpi" tiny --steps 2 --quiet --out mpi
expect_in out.txt "or use a larger influence radius"

# 4. A NaN position at init: every backend names the field and the particle
# as the reference does.
expect_exit 1 timeout -k 5 60 "$scene-reference" nan --steps 2 --quiet --out ref
want="error: step 0: after kernel 'Spawn': field 'pos' of particle 9 is nan"
expect_in out.txt "$want"
expect_exit 1 timeout -k 5 60 "$scene-serial" nan --steps 2 --quiet --out serial
expect_in out.txt "$want"
for n in 2 3; do
  expect_exit 1 mpi "$n" "$scene-mpi" nan --steps 2 --quiet --out mpi
  expect_in out.txt "$want"
done
echo "mpi limits: far particles wrap or are refused with the limit, tiny cells refused, NaN named"
