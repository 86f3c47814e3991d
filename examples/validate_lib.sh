# validate_lib.sh: what examples/<name>/validate.sh scripts share. Sourced with
# `name`, `size` and `end_time` set; builds <name>-$WASH_BACKEND in the build
# tree build/ at the repository root (configured with -DCMAKE_BUILD_TYPE=Release
# if missing), runs it with argument `size` and leaves `root`, `backend`,
# `work` (out/validate/<name>/), `state` (the --dump of the final state),
# `plot` (where the profile plot goes) and `wall` (seconds) set. An array
# `run_options`, if set, adds wash options to the run.
#
# Environment:
#   WASH_BACKEND  reference | serial | openmp | mpi   (default openmp)
#   WASH_RANKS    MPI ranks for WASH_BACKEND=mpi      (default 2)
#   JOBS          parallel build jobs                  (default 2)
backend=${WASH_BACKEND:-openmp}
ranks=${WASH_RANKS:-2}
jobs=${JOBS:-2}

case $backend in
reference | serial | openmp | mpi) ;;
*)
    echo "$0: WASH_BACKEND must be reference, serial, openmp or mpi (not '$backend')" >&2
    exit 2
    ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
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
"${run[@]}" "$size" --quiet --dump "$state" --out "$work/frames" ${run_options[@]+"${run_options[@]}"}
finish=$(date +%s.%N)
wall=$(awk -v a="$start" -v b="$finish" 'BEGIN { printf "%.2f", b - a }')
