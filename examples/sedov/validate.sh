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
backend=${WASH_BACKEND:-openmp}
ranks=${WASH_RANKS:-2}
jobs=${JOBS:-2}
end_time=0.05

if ! [[ $size =~ ^[0-9]+$ ]] || ((size < 8)); then
    echo "usage: $0 [n]   (n >= 8: an n^3 lattice)" >&2
    exit 2
fi
case $backend in
reference | serial | openmp | mpi) ;;
*)
    echo "$0: WASH_BACKEND must be reference, serial, openmp or mpi (not '$backend')" >&2
    exit 2
    ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build
work=$root/out/validate/$name
mkdir -p "$work"
log=$work/build.log

if [[ ! -f $build/CMakeCache.txt ]]; then
    echo "configuring $build"
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >"$log" 2>&1 || {
        cat "$log" >&2
        exit 1
    }
fi
target=$name-$backend
echo "building $target"
cmake --build "$build" --target "$target" -j "$jobs" >"$log" 2>&1 || {
    tail -n 40 "$log" >&2
    echo "$0: building $target failed (full log: $log)" >&2
    exit 1
}

binary=$build/bin/$target
run=("$binary")
if [[ $backend == mpi ]]; then
    mpirun=${MPIRUN:-mpirun}
    flags=()
    if "$mpirun" --version 2>/dev/null | grep -q "Open MPI"; then
        flags+=(--oversubscribe)
        if [[ $(id -u) == 0 ]]; then flags+=(--allow-run-as-root); fi
    fi
    run=("$mpirun" "${flags[@]}" -np "$ranks" "$binary")
fi

state=$work/state_$size.csv
plot=$work/${name}_$size.png
echo "running $target $size (to t = $end_time)"
start=$(date +%s.%N)
"${run[@]}" "$size" --quiet --dump "$state" --out "$work/frames"
finish=$(date +%s.%N)
wall=$(awk -v a="$start" -v b="$finish" 'BEGIN { printf "%.2f", b - a }')

# The blast is at the centre (0.5, 0.5, 0.5) of the periodic unit box.
metrics=$(/usr/bin/python3 "$root/bench/validation/compare.py" "$state" --problem sedov \
    --time "$end_time" --box 1 --plot "$plot" --label "$name $size^3, $backend")
echo "$metrics" | sed '$d'
echo "size=$size backend=$backend wall_s=$wall $(echo "$metrics" | tail -n 1)"
