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
# out/validate/noh/: state_<n>.csv (the --dump of the final state),
# inner_<n>.csv (its particles within NOH_RCUT) and noh_<n>.png (radial
# profiles against the exact solution).
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
backend=${WASH_BACKEND:-openmp}
ranks=${WASH_RANKS:-2}
jobs=${JOBS:-2}
rcut=${NOH_RCUT:-0.3}
end_time=0.6

if ! [[ $size =~ ^[0-9]+$ ]] || ((size < 8)); then
    echo "usage: $0 [n]   (n >= 8: the points of an n^3 lattice in the unit sphere)" >&2
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

# The implosion is centred on the origin; keep the particles inside r < rcut.
inner=$work/inner_$size.csv
/usr/bin/python3 - "$state" "$inner" "$rcut" <<'PY'
import csv, math, sys
source, target, rcut = sys.argv[1], sys.argv[2], float(sys.argv[3])
with open(source, newline="") as fin, open(target, "w", newline="") as fout:
    rows = csv.reader(fin)
    header = next(rows)
    x, y, z = (header.index(c) for c in ("x", "y", "z"))
    out = csv.writer(fout, lineterminator="\n")
    out.writerow(header)
    kept = total = 0
    for row in rows:
        total += 1
        if math.sqrt(float(row[x]) ** 2 + float(row[y]) ** 2 + float(row[z]) ** 2) < rcut:
            out.writerow(row)
            kept += 1
print("kept %d of %d particles (r < %g)" % (kept, total, rcut))
PY
metrics=$(/usr/bin/python3 "$root/bench/validation/compare.py" "$inner" --problem noh \
    --time "$end_time" --plot "$plot" --label "$name $size, $backend, r < $rcut")
echo "$metrics" | sed '$d'
echo "size=$size backend=$backend wall_s=$wall rcut=$rcut $(echo "$metrics" | tail -n 1)"
