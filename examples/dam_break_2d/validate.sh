#!/usr/bin/env bash
# validate.sh [n]: build the dam_break_2d example, run it with n particles
# across the column (default 40: 4,418 particles, about 40 s of CPU, 1-3
# minutes on two shared cores) to T = t sqrt(2g/L) = 3.2, and score its surge front against Martin &
# Moyce (1952) and Koshizuka & Oka (1996) with front.py: the mean relative
# error over T <= 3 (standard inviscid WCSPH runs 5-10 % ahead of the data;
# the target is +12 % at most against Martin & Moyce).
#
# Works from any directory. Reuses the build tree build/ at the repository root
# (configured with -DCMAKE_BUILD_TYPE=Release if it is missing). Writes into
# out/validate/dam_break_2d/: state_<n>.csv (the --dump of the final state),
# front_<n>.txt (the program's front lines) and dam_break_2d_<n>.png (the
# front against the experiments).
#
# Environment:
#   WASH_BACKEND  reference | serial | openmp | mpi   (default serial: the
#                 scene is small, and serial is fastest on a busy machine)
#   WASH_RANKS    MPI ranks for WASH_BACKEND=mpi      (default 2)
#   JOBS          parallel build jobs                  (default 2)
#
# The last line of output holds the metrics as key=value pairs:
#   size=<n> backend=<b> wall_s=<run time> mm_error=... mm1125_error=... ko_error=...
set -euo pipefail

name=dam_break_2d
size=${1:-40}
end_time="T = 3.2"
export WASH_BACKEND=${WASH_BACKEND:-serial}

if ! [[ $size =~ ^[0-9]+$ ]] || ((size < 4)); then
    echo "usage: $0 [n]   (n >= 4 particles across the column)" >&2
    exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
front_log=$(cd "$here/../.." && pwd)/out/validate/$name/front_$size.txt
mkdir -p "$(dirname "$front_log")"
# The program prints its front lines on stdout: keep them (MPI ranks each
# print them, so keep one copy).
. "$here/../validate_lib.sh" > >(awk '!seen[$0]++' | tee "$front_log")
wait

metrics=$(/usr/bin/python3 "$here/front.py" "$front_log" --plot "$plot" \
    --label "wash dam_break_2d, n = $size ($backend)")
echo "$metrics" | sed '$d'
echo "size=$size backend=$backend wall_s=$wall $(echo "$metrics" | tail -n 1)"
