# The closed system (closed_box.cpp: periodic box, no walls, no external force,
# momentum-conserving artificial viscosity) keeps its total energy and momentum,
# step by step, in the translated OpenMP program; the reference prints the same
# per-step log, bit for bit, for the first steps.
#   closed_box_conservation.sh BIN STEPS REFERENCE_STEPS
. "$(dirname "$0")/lib.sh"
bin=$1 steps=$2 reference_steps=$3

# Bounds, as fractions of the initial total energy E0 (drift.awk defines the
# measures). Measured at 3001 steps: 1.40e-5, 2.5e-7, 4.2e-8, 6.9e-17; the
# energy error is the leapfrog's, made while the initial flow steepens into
# shocks, and shrinks about 8-fold each time dt is halved (docs/validation.md).
max_energy_drift=5e-5       # |E(s) - E0| / E0, any step
max_energy_step_drift=1e-6  # |E(s) - E(s-1)| / E0
max_late_energy_drift=2e-7  # over the second half: no secular growth once the shocks are gone
max_momentum_drift=1e-12    # |P(s) - P0| in units of M c0 (= 1): rounding only
max_kinetic_ratio=0.25      # the run did something: shocks turned 3/4 of the kinetic energy into heat

expect_exit 0 "$bin/closed_box-openmp" --steps "$steps"
cp out.txt openmp.txt
expect_in openmp.txt "wash: $steps steps of 1024 particles"
summary=$(drift openmp.txt)
echo "closed_box-openmp (OMP_NUM_THREADS=$OMP_NUM_THREADS): $summary"
[ "$(field steps "$summary")" -eq "$steps" ] || fail "expected $steps step lines: $summary"
at_most energy_drift "$(field energy_drift "$summary")" $max_energy_drift
at_most energy_step_drift "$(field energy_step_drift "$summary")" $max_energy_step_drift
at_most late_energy_drift "$(field late_energy_drift "$summary")" $max_late_energy_drift
at_most momentum_drift "$(field momentum_drift "$summary")" $max_momentum_drift
at_most kinetic_ratio "$(field kinetic_ratio "$summary")" $max_kinetic_ratio

# The untranslated program defines the run: same lines, same bits.
expect_exit 0 "$bin/closed_box-reference" --steps "$reference_steps"
grep '^step=' out.txt > reference.log
[ "$(wc -l < reference.log)" -eq "$reference_steps" ] || fail "expected $reference_steps step lines from the reference"
grep '^step=' openmp.txt | head -n "$reference_steps" | cmp -s - reference.log ||
  fail "the reference's per-step log differs from the OpenMP program's: $(grep '^step=' openmp.txt | head -n "$reference_steps" | diff - reference.log | head -4)"
echo "closed_box: energy and momentum conserved within bounds over $steps steps; reference log identical for $reference_steps steps"
