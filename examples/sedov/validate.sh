#!/usr/bin/env bash
# validate.sh [n]: build the sedov example, run it on an n^3 lattice (default
# 30, about 10-20 s with OpenMP on two cores) to t = 0.05, and score the final
# state against the exact Sedov-Taylor solution with bench/validation/compare.py.
#
# Works from any directory. Reuses the build tree build/ at the repository root
# (configured with -DCMAKE_BUILD_TYPE=Release if it is missing). Writes into
# out/validate/sedov/: state_<n>.csv (the --dump of the final state) and
# sedov_<n>.png (radial profiles against the exact solution).
#
# Environment:
#   WASH_BACKEND  reference | serial | openmp | mpi   (default openmp)
#   WASH_RANKS    MPI ranks for WASH_BACKEND=mpi      (default 2)
#   JOBS          parallel build jobs                  (default 2)
#
# The last line of output holds the metrics as key=value pairs:
#   size=<n> backend=<b> wall_s=<run time> l1_density=... (compare.py's line)
set -euo pipefail

name=sedov
size=${1:-30}
end_time=0.05
# The run ends at the end time; a frame (out/validate/sedov/frames/) every 0.01.
run_options=(--end-time "$end_time" --output-dt 0.01)

if ! [[ $size =~ ^[0-9]+$ ]] || ((size < 8)); then
    echo "usage: $0 [n]   (n >= 8: an n^3 lattice)" >&2
    exit 2
fi
. "$(dirname "${BASH_SOURCE[0]}")/../validate_lib.sh"

# The blast is at the centre (0.5, 0.5, 0.5) of the periodic unit box.
metrics=$(/usr/bin/python3 "$root/bench/validation/compare.py" "$state" --problem sedov \
    --time "$end_time" --box 1 --plot "$plot" --label "$name $size^3, $backend")
echo "$metrics" | sed '$d'
echo "size=$size backend=$backend wall_s=$wall $(echo "$metrics" | tail -n 1)"
