# Particle types (scenes/particle_types.cpp): every backend named writes the
# reference's --dump byte for byte (OpenMP at 1 and 2 threads, MPI at 2 and 3
# ranks, the serial program with both scan paths), and the dump shows what
# the types mean: a type column, the walls' count and their untouched
# velocities (no fluid kernel ran for them), fluid turned sediment by
# set_type; VTK frames name the types in their field data.
. "$(dirname "$0")/lib.sh"
bin=$1 mpiexec=$2
shift 2
steps=100

expect_exit 0 "$bin/particle_types-reference" --steps $steps --quiet --dump reference.csv \
  --out ref --output-every 50
head -1 reference.csv | grep -qx 'id,x,y,vx,vy,density,mass,smoothing_length,age,type' ||
  fail "the typed dump's header is $(head -1 reference.csv)"
# 3 floor rows of 36 and two walls of 3 x 16 are type 1; 168 fluid particles start as type 0.
walls=$(awk -F, 'NR > 1 && $10 == 1' reference.csv | wc -l)
[ "$walls" = 204 ] || fail "$walls wall particles, not 204"
moving=$(awk -F, 'NR > 1 && $10 == 1 && ($4 != 0 || $5 != 0)' reference.csv | wc -l)
[ "$moving" = 0 ] || fail "$moving wall particles have a velocity: a fluid kernel ran for them"
fluid=$(awk -F, 'NR > 1 && $10 == 0' reference.csv | wc -l)
sediment=$(awk -F, 'NR > 1 && $10 == 2' reference.csv | wc -l)
[ $((fluid + sediment)) = 168 ] && [ "$sediment" -gt 0 ] && [ "$fluid" -gt 0 ] ||
  fail "$fluid fluid and $sediment sediment particles: set_type did not happen as expected"
aged=$(awk -F, 'NR > 1 && $9 > 0 && $10 != 2' reference.csv | wc -l)
[ "$aged" = 0 ] || fail "$aged particles that are not sediment ran the sediment kernel"
grep -aq 'Name="type_wall" NumberOfTuples="1" format="ascii">1<' ref/particle_types_000100.vtp ||
  fail "the VTK frame does not name the types in its field data"

for backend in "$@"; do
  if [ "$backend" = mpi ]; then
    [ -n "$mpiexec" ] || { echo "skipped mpi: no mpiexec"; continue; }
    for ranks in 2 3; do
      OMP_NUM_THREADS=1 expect_exit 0 timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe \
        -np $ranks "$bin/particle_types-mpi" --steps $steps --quiet --dump mpi-$ranks.csv \
        --out mpi-$ranks
      cmp -s reference.csv mpi-$ranks.csv ||
        fail "particle_types-mpi on $ranks ranks differs from the reference: $(cmp reference.csv mpi-$ranks.csv)"
    done
    continue
  fi
  for threads in 1 2; do
    [ "$backend" = serial ] && [ $threads != 1 ] && continue
    OMP_NUM_THREADS=$threads expect_exit 0 "$bin/particle_types-$backend" --steps $steps --quiet \
      --dump $backend-$threads.csv --out $backend-$threads --output-every 50
    cmp -s reference.csv $backend-$threads.csv ||
      fail "particle_types-$backend with $threads threads differs from the reference: $(cmp reference.csv $backend-$threads.csv)"
    # Frames hold rows in storage order: only the type names are compared.
    cmp -s <(grep -a 'Name="type_' ref/particle_types_000100.vtp) \
      <(grep -a 'Name="type_' $backend-$threads/particle_types_000100.vtp) ||
      fail "particle_types-$backend's VTK frame names the types otherwise"
  done
done
if [ -x "$bin/particle_types-serial" ]; then
  WASH_SCALAR_SCAN=1 expect_exit 0 "$bin/particle_types-serial" --steps $steps --quiet \
    --dump scalar.csv --out scalar
  cmp -s reference.csv scalar.csv || fail "particle_types-serial with the scalar scan differs"
fi
echo "particle_types: $* identical to the reference after $steps steps ($fluid fluid, $walls wall, $sediment sediment)"
