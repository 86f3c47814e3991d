# wash run: one command from a scene to its run. A scene with a header of its
# own is translated and built into the cache ($XDG_CACHE_HOME/wash) by two
# runs at once (one builds, the other waits and finds it built), run again
# with no rebuild (the program's and the generated source's timestamps stay),
# rebuilt after an edit to its header, run untranslated (--reference) and on
# two MPI ranks, each computing the same dump. A scene with an error stops at
# the user's line; a build that fails shows the compiler's output; the
# program's exit status is wash run's; `wash cache clean` empties the cache.
. "$(dirname "$0")/lib.sh"
wash=$1 scene_dir=$2 mpi=${3:-}

cp -r "$scene_dir" src
# A scene with an error, and one that fails to link (a function declared,
# never defined).
sed 's/^    p.set_density(density);$/&\n    p.set_pos(n.get_pos());/' src/drift.cpp > src/bad.cpp
line=$(grep -n 'p.set_pos(n.get_pos());' src/bad.cpp | cut -d: -f1)
[ -n "$line" ] || fail "could not write the bad scene"
sed -e 's/^void Move(wash::Particle& p) {$/double Undefined(double);\n\n&/' \
  -e 's/p.get_vel() \* 0.01/p.get_vel() * Undefined(0.01)/' src/drift.cpp > src/unlinked.cpp
grep -qF "Undefined(0.01)" src/unlinked.cpp || fail "could not write the unlinked scene"
export XDG_CACHE_HOME="$work/cache"
user_sums() { (cd src && find . -type f | sort | xargs sha256sum); }
user_sums > sums-before.txt

# Two runs at once on an empty cache. A successful build says nothing.
"$wash" run src/drift.cpp -- --steps 5 --quiet --dump first.csv --out o1 > first.txt 2>&1 &
first=$!
"$wash" run src/drift.cpp -- --steps 5 --quiet --dump second.csv --out o2 > second.txt 2>&1 &
second=$!
wait $first || { cat first.txt >&2; fail "the first of two runs at once failed"; }
wait $second || { cat second.txt >&2; fail "the second of two runs at once failed"; }
[ -s first.txt ] && { cat first.txt >&2; fail "a run that built its program printed output"; }
[ -s second.txt ] && { cat second.txt >&2; fail "a run that waited for a build printed output"; }
cmp -s first.csv second.csv || fail "two runs at once computed different dumps"

program=$(find cache/wash -type f -name drift-serial)
[ -n "$program" ] && [ "$(echo "$program" | wc -l)" = 1 ] ||
  fail "expected one drift-serial program in the cache, found: $program"
generated=$(dirname "$(dirname "$program")")/project/drift.serial.cpp
[ -f "$generated" ] || fail "no generated source beside the program: $generated"
stamps() { stat -c '%y' "$program" "$generated"; }
before=$(stamps)

# Nothing changed, or the header only touched: nothing is translated or built.
expect_exit 0 "$wash" run src/drift.cpp -- --steps 5 --quiet --dump again.csv
[ "$(stamps)" = "$before" ] || fail "a run of an unchanged scene rebuilt it"
cmp -s first.csv again.csv || fail "a second run computed another dump"
touch src/drift.hpp
expect_exit 0 "$wash" run src/drift.cpp -- --steps 5 --quiet --dump again.csv
[ "$(stamps)" = "$before" ] || fail "touching the header, with no change, rebuilt the scene"

# An edit to the header rebuilds.
sed -i 's/DriftSpeed = 0.5;/DriftSpeed = 0.7;/' src/drift.hpp
grep -qF "DriftSpeed = 0.7;" src/drift.hpp || fail "the test's edit did not apply"
user_sums > sums-before.txt
expect_exit 0 "$wash" run src/drift.cpp -- --steps 5 --quiet --dump edited.csv
[ "$(stamps)" = "$before" ] && fail "an edit to the header did not rebuild the scene"
cmp -s first.csv edited.csv && fail "the program rebuilt after the header's edit computes the same dump"

# The untranslated program, and MPI ranks: the same dump.
expect_exit 0 "$wash" run --reference src/drift.cpp -- --steps 5 --quiet --dump reference.csv
[ -n "$(find cache/wash -type f -name drift-reference)" ] || fail "--reference built no drift-reference"
cmp -s edited.csv reference.csv || fail "the reference program's dump differs from the serial one's"
if [ -n "$mpi" ]; then
  expect_exit 0 "$wash" run --np 2 src/drift.cpp -- --steps 5 --dump mpi.csv --out o3
  grep -qE "\b2 ranks" out.txt || { cat out.txt >&2; fail "--np 2 did not run two ranks"; }
  cmp -s edited.csv mpi.csv || fail "two MPI ranks computed another dump than the serial program"
fi
expect_exit 1 "$wash" run --reference --np 2 src/drift.cpp
expect_in out.txt "error: --reference runs the untranslated program"

# The program's exit status is wash run's, its messages under its own name.
expect_exit 2 "$wash" run src/drift.cpp -- --no-such-option
expect_in out.txt "drift-serial: error: unknown option '--no-such-option'"

# An error in the scene: at the user's line, translated or not, and nothing runs.
for mode in "" --reference; do
  expect_exit 1 "$wash" run $mode src/bad.cpp -- --dump bad.csv
  expect_in out.txt "bad.cpp:$line:15: error: use of undeclared identifier 'n'"
  [ -e bad.csv ] && fail "wash run $mode ran a scene with an error"
done
# A build that fails: the linker's output.
expect_exit 1 "$wash" run --reference src/unlinked.cpp
expect_in out.txt "wash: error: building the reference program of 'src/unlinked.cpp' failed"
expect_in out.txt "Undefined(double)"

user_sums > sums-after.txt
cmp -s sums-before.txt sums-after.txt || fail "wash run wrote into the user's folder"
expect_exit 0 "$wash" cache clean
[ -e cache/wash ] && fail "wash cache clean left $(find cache/wash | head -5)"
echo "wash run: cached builds, rebuilt on a header's edit, --reference, MPI, errors at the user's line"
