#!/usr/bin/env bash
# validate.sh [n]: build the noh example, run it with the points of an n^3
# lattice inside the unit sphere (default 30: 14,328 particles, about 15-30 s
# with OpenMP on two cores) to t = 0.6, and score the particles within
# r < 0.3 of the centre (NOH_RCUT), where the sphere's free outer edge (at
# r = 0.4 by then) has no effect, against the exact Noh solution with
# bench/validation/compare.py.
#
# Works from any directory. Reuses the build tree build/ at the repository root
# (configured with -DCMAKE_BUILD_TYPE=Release if it is missing). Writes into
# out/validate/noh/: state_<n>.csv (the --dump of the final state) and
# noh_<n>.png (radial profiles against the exact solution).
#
# Environment:
#   WASH_BACKEND  reference | serial | openmp | mpi   (default openmp)
#   WASH_RANKS    MPI ranks for WASH_BACKEND=mpi      (default 2)
#   JOBS          parallel build jobs                  (default 2)
#   NOH_RCUT      compare the particles with r < NOH_RCUT (default 0.3)
#
# The last line of output holds the metrics as key=value pairs:
#   size=<n> backend=<b> wall_s=<run time> rcut=<r> l1_density=... (compare.py's line)
set -euo pipefail

name=noh
size=${1:-30}
rcut=${NOH_RCUT:-0.3}
end_time=0.6

if ! [[ $size =~ ^[0-9]+$ ]] || ((size < 8)); then
    echo "usage: $0 [n]   (n >= 8: the points of an n^3 lattice in the unit sphere)" >&2
    exit 2
fi
. "$(dirname "${BASH_SOURCE[0]}")/../validate_lib.sh"

# The implosion is centred on the origin; score the particles inside r < rcut.
metrics=$(/usr/bin/python3 "$root/bench/validation/compare.py" "$state" --problem noh \
    --time "$end_time" --rmax "$rcut" --plot "$plot" --label "$name $size, $backend, r < $rcut")
echo "$metrics" | sed '$d'
echo "size=$size backend=$backend wall_s=$wall rcut=$rcut $(echo "$metrics" | tail -n 1)"
