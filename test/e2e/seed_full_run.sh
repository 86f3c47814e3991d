# The seed example's promise: 1000 steps without NaN, every particle inside the
# 17.1 x 9.3 box, and the same --dump from two runs.
. "$(dirname "$0")/lib.sh"
sim=$1

expect_exit 0 "$sim" --quiet --dump a.csv
expect_exit 0 "$sim" --quiet --dump b.csv --out other
cmp -s a.csv b.csv || fail "two runs gave different dumps"
[ "$(wc -l < a.csv)" -eq 4033 ] || fail "expected 4032 particles and a header"

# The true position is the 'position' force, clamped to the walls by HandleCollisions.
read -r lo hi <<<"$(csv_range a.csv position_x)"
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo >= -8.55 && hi <= 8.55) }' || fail "x outside the box: $lo $hi"
read -r lo hi <<<"$(csv_range a.csv position_y)"
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo >= -4.65 && hi <= 4.65) }' || fail "y outside the box: $lo $hi"
# pos is the position predicted 1/120 s ahead: at most a few hundredths out.
read -r lo hi <<<"$(csv_range a.csv x)"
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo > -8.65 && hi < 8.65) }' || fail "pos.x far outside: $lo $hi"
# Settled: the water stays in the lower part of the box, near the target density.
read -r lo hi <<<"$(csv_range a.csv density)"
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo > 40 && hi < 75) }' || fail "density out of range: $lo $hi"
echo "seed: 1000 steps, inside the box, identical dumps"
