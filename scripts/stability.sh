#!/usr/bin/env bash
# The long stability runs of issue #6 (the short ones are the ctest tests
# stability.*, test/stability/):
#   1. the seed scene (examples/ca_fluid_sim, translated for OpenMP) for
#      SEED_STEPS steps (default 100000): no non-finite value (the runtime
#      would stop with a message and exit 1), and no particle outside the
#      17.1 x 9.3 box in any frame (CSV every EVERY steps, default 1000);
#   2. the closed system test/stability/closed_box.cpp for BOX_STEPS steps
#      (default 100001, i.e. 100000 time steps): its total energy and momentum,
#      logged every step, must drift less than the bounds of the CI test.
#
#   bash scripts/stability.sh [SEED_STEPS [BOX_STEPS [EVERY]]]
#
# Works from any directory; reuses build/ (configures it, Release, if missing)
# and builds only the two programs it runs. Writes out/stability/:
#   seed.csv           one row per frame: extent of the particles, max speed,
#                      kinetic and potential energy, density range, escaped count
#   seed_final.csv     the seed's final state (--dump)
#   seed.log           the seed run's output
#   closed_box.log     the closed box's output, one line per step
#   closed_box.csv     per step: energy, kinetic energy, momentum and their drifts
#   stability.png      plots of both, if /usr/bin/python3 has matplotlib
#   build.log          the output of building the two programs
# and ends with one line of key=value pairs; the exit status is 0 only if
# every check passed.
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

seed_steps=${1:-100000}
box_steps=${2:-100001}
every=${3:-1000}
for n in "$seed_steps" "$box_steps" "$every"; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "usage: scripts/stability.sh [SEED_STEPS [BOX_STEPS [EVERY]]] (positive integers)" >&2; exit 2; }
done
(( box_steps >= 2 )) || { echo "BOX_STEPS must be at least 2" >&2; exit 2; }

# Bounds: the same as the CI test test/stability/closed_box_conservation.sh
# (fractions of the initial total energy; momentum in units of M c0 = 1).
max_energy_drift=5e-5
max_energy_step_drift=1e-6
max_late_energy_drift=2e-7
max_momentum_drift=1e-12

export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
out=out/stability
mkdir -p "$out"
bin=build/bin

if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release || exit 1
fi
echo "building ca_fluid_sim-openmp and closed_box-openmp in build/ (log: $out/build.log)"
cmake --build build -j2 --target ca_fluid_sim-openmp closed_box-openmp >"$out/build.log" 2>&1 || {
  tail -30 "$out/build.log" >&2; echo "stability: could not build ca_fluid_sim-openmp and closed_box-openmp" >&2; exit 1; }

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
status=ok

# --- 1. the seed scene -------------------------------------------------------
echo "== seed scene: $seed_steps steps, a frame every $every steps (OMP_NUM_THREADS=$OMP_NUM_THREADS)"
frames=$(mktemp -d "$out/seed_frames.XXXXXX")
trap 'rm -rf "$frames"' EXIT
start=$(now)
"$bin/ca_fluid_sim-openmp" seed --steps "$seed_steps" --out "$frames" --format csv \
  --output-every "$every" --dump "$out/seed_final.csv" >"$out/seed.log" 2>&1
seed_exit=$?
seed_wall=$(elapsed "$start" "$(now)")
seed_error=$(grep -m1 'error:' "$out/seed.log")
# One row per frame. The true position is the force 'position' (clamped to the
# walls, |x| <= 8.55, |y| <= 4.65); pos is it predicted 1/120 s ahead. Energy
# per particle (mass 1): kinetic v^2/2, potential 12 (y + 4.65) (gravity 12).
echo "step,position_x_min,position_x_max,position_y_min,position_y_max,x_min,x_max,y_min,y_max,max_speed,kinetic_per_particle,potential_per_particle,density_min,density_max,escaped,non_finite" >"$out/seed.csv"
for f in "$frames"/seed_*.csv; do
  [ -e "$f" ] || continue
  step=${f##*_}; step=$((10#${step%.csv}))
  awk -F, -v step="$step" '
    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    {
      for (i = 1; i <= NF; i++) if (tolower($i) ~ /nan|inf/) bad++
      px = $c["position_x"]; py = $c["position_y"]; x = $c["x"]; y = $c["y"]; d = $c["density"]
      s = $c["vx"] * $c["vx"] + $c["vy"] * $c["vy"]
      if (NR == 2) { pxl = pxh = px; pyl = pyh = py; xl = xh = x; yl = yh = y; dl = dh = d; m = s }
      if (px < pxl) pxl = px; if (px > pxh) pxh = px; if (py < pyl) pyl = py; if (py > pyh) pyh = py
      if (x < xl) xl = x; if (x > xh) xh = x; if (y < yl) yl = y; if (y > yh) yh = y
      if (d < dl) dl = d; if (d > dh) dh = d; if (s > m) m = s
      k += 0.5 * s; pot += 12.0 * (py + 4.65)
      if (px < -8.55 || px > 8.55 || py < -4.65 || py > 4.65) out++
    }
    END {
      n = NR - 1
      printf "%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%d\n", step, pxl, pxh, pyl, pyh,
        xl, xh, yl, yh, sqrt(m), k / n, pot / n, dl, dh, out + 0, bad + 0
    }' "$f"
done | sort -t, -k1,1n >>"$out/seed.csv"
seed_frames=$(($(wc -l <"$out/seed.csv") - 1))
read -r seed_escaped seed_nonfinite seed_max_speed seed_kinetic <<<"$(awk -F, 'NR > 1 {
    e += $15; b += $16; if ($10 > m) m = $10; k = $11 } END { printf "%d %d %.4g %.4g", e, b, m, k }' "$out/seed.csv")"
seed_status=ok
if [ "$seed_exit" -ne 0 ]; then
  seed_status=fail; echo "seed: exited $seed_exit: ${seed_error:-see $out/seed.log}"
fi
if [ "$seed_frames" -ne $((seed_steps / every + 1 + (seed_steps % every != 0))) ]; then
  seed_status=fail; echo "seed: $seed_frames frames written"
fi
if [ "$seed_escaped" -ne 0 ] || [ "$seed_nonfinite" -ne 0 ]; then
  seed_status=fail; echo "seed: $seed_escaped particle-frames outside the box, $seed_nonfinite non-finite values"
fi
[ "$seed_status" = ok ] || status=fail
echo "seed: status=$seed_status exit=$seed_exit frames=$seed_frames escaped=$seed_escaped non_finite=$seed_nonfinite max_speed=$seed_max_speed final_kinetic_per_particle=$seed_kinetic wall=${seed_wall}s"
rm -rf "$frames"

# --- 2. the closed box ---------------------------------------------------------
echo "== closed box: $box_steps steps ($((box_steps - 1)) time steps), energy and momentum every step"
start=$(now)
"$bin/closed_box-openmp" --steps "$box_steps" >"$out/closed_box.log" 2>&1
box_exit=$?
box_wall=$(elapsed "$start" "$(now)")
box_summary=$(awk -f test/stability/drift.awk -v csv="$out/closed_box.csv" "$out/closed_box.log") || box_summary=""
get() { tr ' ' '\n' <<<"$box_summary" | sed -n "s/^$1=//p"; }
over() { awk -v v="$1" -v b="$2" 'BEGIN { exit !(v == "" || v + 0 > b + 0) }'; }
box_status=ok
if [ "$box_exit" -ne 0 ] || [ -z "$box_summary" ] || [ "$(get steps)" != "$box_steps" ]; then
  box_status=fail; echo "closed box: exited $box_exit; $(grep -m1 'error:' "$out/closed_box.log")"
fi
checks=("energy_drift $max_energy_drift" "energy_step_drift $max_energy_step_drift" "momentum_drift $max_momentum_drift")
# The second half of the run is past the shocks (t > 7.6) only from 3001 steps on.
if (( box_steps >= 3001 )); then
  checks+=("late_energy_drift $max_late_energy_drift")
else
  echo "closed box: late_energy_drift not checked: the second half of $box_steps steps is not past the shocks (needs 3001 steps)"
fi
for check in "${checks[@]}"; do
  set -- $check
  if over "$(get "$1")" "$2"; then box_status=fail; echo "closed box: $1=$(get "$1") exceeds $2"; fi
done
[ "$box_status" = ok ] || status=fail
echo "closed box: status=$box_status $box_summary wall=${box_wall}s"

# --- plot -------------------------------------------------------------------------
plot=none
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  /usr/bin/python3 - "$out" <<'EOF' && plot="$out/stability.png"
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
def read(name):
    with open(f"{out}/{name}") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else None

box, seed = read("closed_box.csv"), read("seed.csv")
fig, ax = plt.subplots(2, 2, figsize=(12, 8))
if box:
    t = box["step"]  # log scale: the shocks, and all of the energy error, come in the first 1000 steps
    ax[0][0].plot(t, box["energy_drift"])
    ax[0][0].set(title="closed box: (E - E0) / E0 (kinetic energy grey)", xlabel="step", xscale="log")
    k = ax[0][0].twinx()
    k.plot(t, box["kinetic"], color="grey", lw=0.8)
    k.set_ylabel("kinetic energy")
    ax[0][1].plot(t, box["momentum_x_drift"], label="x", lw=0.5)
    ax[0][1].plot(t, box["momentum_y_drift"], label="y", lw=0.5)
    ax[0][1].set(title="closed box: P - P0 (units of M c0)", xlabel="step", xscale="log")
    ax[0][1].legend()
if seed:
    s = seed["step"]
    ax[1][0].plot(s, seed["kinetic_per_particle"])
    ax[1][0].set(title="seed: energy per particle (potential grey)", xlabel="step", yscale="log",
                 ylabel="kinetic")
    p = ax[1][0].twinx()
    p.plot(s, seed["potential_per_particle"], color="grey", lw=0.8)
    p.set_ylabel("potential, 12 (y + 4.65)")
    for key in ("position_x_min", "position_x_max", "position_y_min", "position_y_max"):
        ax[1][1].plot(s, seed[key], label=key)
    for v in (-8.55, 8.55, -4.65, 4.65):
        ax[1][1].axhline(v, color="k", lw=0.5, ls="--")
    ax[1][1].set(title="seed: particle extent (walls dashed)", xlabel="step")
    ax[1][1].legend(fontsize=7)
fig.tight_layout()
fig.savefig(f"{out}/stability.png", dpi=90)
EOF
fi

echo "status=$status seed_steps=$seed_steps seed_status=$seed_status seed_escaped=$seed_escaped seed_non_finite=$seed_nonfinite seed_wall_s=$seed_wall box_steps=$box_steps box_status=$box_status box_energy_drift=$(get energy_drift) box_late_energy_drift=$(get late_energy_drift) box_momentum_drift=$(get momentum_drift) box_wall_s=$box_wall threads=$OMP_NUM_THREADS out=$out plot=$plot"
[ "$status" = ok ]
