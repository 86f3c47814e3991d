#!/usr/bin/env bash
# sedov_convergence.sh - run time against error for the Sedov blast wave.
#
# Translates examples/sedov/sedov.cpp for the chosen backend in double and in
# float precision, runs it at each lattice size n (n^3 particles) to t = 0.05,
# scores each final state against the exact solution
# (bench/validation/compare.py) and prints one table:
#
#   n, particles, precision, steps, wall s, ns per particle-step, density L1
#   (SPH-EXA's metric: mean |rho - rho_exact|), normalised L1, peak density,
#   shock-radius error
#
# with the convergence order of L1 between successive sizes (L1 ~ dx^order,
# dx = 1/n), a CSV and a plot of L1 against wall time (log-log). Wall time is
# the run's own "steps ... in T s" line (the steps alone, without set-up).
# Nothing is asserted: this is a benchmark.
#
# usage: bench/sedov_convergence.sh [--sizes "30 50 70"] [--precisions "double float"]
#                                   [--backend serial|openmp] [--threads T] [--out DIR]
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
sizes="30 50 70"
precisions="double float"
backend=serial
threads=1
out=$root/out/convergence
while [[ $# -gt 0 ]]; do
  case $1 in
    --sizes) sizes=$2; shift 2 ;;
    --precisions) precisions=$2; shift 2 ;;
    --backend) backend=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "sedov_convergence.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done

build=$root/build
if [[ ! -x $build/bin/wash ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j2 --target wash wash_${backend} >/dev/null
fi
mkdir -p "$out"
csv=$out/convergence.csv
echo "n,particles,precision,backend,threads,steps,wall_s,ns_per_particle_step,l1_density,l1_density_norm,peak_density,shock_radius_error" >"$csv"

for precision in $precisions; do
  # The precision is a translation-time constant: one translated program each.
  src=$out/src/sedov_$precision.cpp
  mkdir -p "$out/src"
  sed "s/wash::set_precision(\"double\")/wash::set_precision(\"$precision\")/" \
    "$root/examples/sedov/sedov.cpp" >"$src"
  grep -q "set_precision(\"$precision\")" "$src" || { echo "cannot set precision $precision" >&2; exit 1; }
  project=$out/sedov_$precision-$backend
  "$build/bin/wash" --backend="$backend" "$src" -o "$project" 2>/dev/null
  cmake -S "$project" -B "$project/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$project/build" -j2 >/dev/null
  program=$(find "$project/build" -maxdepth 2 -type f -executable -name "sedov_$precision*" | head -1)
  [[ -x $program ]] || { echo "no program built in $project/build" >&2; exit 1; }

  for n in $sizes; do
    run=$out/run_${precision}_$n
    rm -rf "$run"
    mkdir -p "$run"
    echo "sedov n=$n ($((n * n * n)) particles), $precision, $backend x $threads ..." >&2
    OMP_NUM_THREADS=$threads "$program" "$n" --dump "$run/state.csv" --out "$run/frames" \
      --output-every 0 >"$run/log.txt" 2>&1 || { cat "$run/log.txt" >&2; exit 1; }
    # "wash: S steps of N particles in T s (...)"
    read -r steps particles wall < <(sed -n 's/^wash: \([0-9]*\) steps of \([0-9]*\) particles in \([0-9.]*\) s.*/\1 \2 \3/p' "$run/log.txt")
    metrics=$(/usr/bin/python3 "$root/bench/validation/compare.py" "$run/state.csv" --problem sedov \
      --time 0.05 --box 1 --plot "$run/profile.png" --label "wash $backend, $precision, $n^3" | tail -1)
    get() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" <<<"$metrics"; }
    ns=$(awk -v w="$wall" -v s="$steps" -v p="$particles" 'BEGIN { printf "%.1f", w * 1e9 / (s * p) }')
    echo "$n,$particles,$precision,$backend,$threads,$steps,$wall,$ns,$(get l1_density),$(get l1_density_norm),$(get peak_density),$(get shock_radius_error)" >>"$csv"
  done
done

/usr/bin/python3 "$root/bench/validation/convergence_plot.py" "$csv" "$out/error_vs_time.png"
