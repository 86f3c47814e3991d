# wash_add_simulation re-translates and rebuilds when a header the simulation
# includes changes: a small CMake project (the multi_file scene, its headers
# in a subfolder and on an INCLUDE_DIRECTORIES path) configured against this
# build of wash, built, then built again after touching and after editing
# headers at include depth 2 and on the include path. The user's files are
# never written.
. "$(dirname "$0")/lib.sh"
package_dir=$1 scene_dir=$2 generator=${3:-Ninja}

cp -r "$scene_dir" src
cat > src/CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(rebuild_on_change LANGUAGES CXX)
find_package(wash REQUIRED CONFIG)
wash_add_simulation(sim SOURCE multi_file.cpp BACKEND serial INCLUDE_DIRECTORIES include)
CMAKE
user_sums() { (cd src && find . -type f ! -name CMakeLists.txt | sort | xargs sha256sum); }

expect_exit 0 cmake -S src -B bld -G "$generator" -Dwash_DIR="$package_dir"
expect_exit 0 cmake --build bld
expect_in out.txt "wash: translating multi_file"
[ -x bld/sim ] || fail "the first build made no program"
expect_exit 0 bld/sim --steps 20 --quiet --dump first.csv --out run
user_sums > sums-before.txt

# Nothing changed: nothing is translated.
expect_exit 0 cmake --build bld
grep -qF "wash: translating" out.txt && { cat out.txt >&2; fail "a build with nothing changed re-translated"; }

# build_after WHAT: the build after a change re-translates and recompiles.
build_after() {
  expect_exit 0 cmake --build bld
  grep -qF "wash: translating multi_file" out.txt ||
    { cat out.txt >&2; fail "$1: the build did not re-translate"; }
  grep -qE "Building CXX object|Linking CXX executable" out.txt ||
    { cat out.txt >&2; fail "$1: the build did not recompile the program"; }
}

# A touch at include depth 2 re-translates (the content is the same).
sleep 1
touch src/scene/detail/geometry.hpp
build_after "touching scene/detail/geometry.hpp"

# A change at depth 2 changes the program.
sleep 1
sed -i 's/constexpr double FloorY = 0.05;/constexpr double FloorY = 0.09;/' src/scene/detail/geometry.hpp
grep -qF "FloorY = 0.09" src/scene/detail/geometry.hpp || fail "the test's edit did not apply"
build_after "editing scene/detail/geometry.hpp"
grep -rqF "FloorY = 0.09" bld/sim.wash/user || fail "the generated copy of geometry.hpp was not rewritten"
expect_exit 0 bld/sim --steps 20 --quiet --dump second.csv --out run
cmp -s first.csv second.csv && fail "the program built after editing the header computes the same dump"

# A change in a header found on INCLUDE_DIRECTORIES.
sleep 1
sed -i 's/strength \*= 2.0;/strength *= 3.0;/' src/include/forces/pair.hpp
build_after "editing include/forces/pair.hpp"
expect_exit 0 bld/sim --steps 20 --quiet --dump third.csv --out run
cmp -s second.csv third.csv && fail "the program built after editing pair.hpp computes the same dump"

# wash wrote only into the build folder.
user_sums > sums-after.txt
diff <(grep -v -e geometry.hpp -e pair.hpp sums-before.txt) <(grep -v -e geometry.hpp -e pair.hpp sums-after.txt) ||
  fail "a user file was changed by the build"
echo "rebuild on change ($generator): touching and editing headers at depth 2 and on the include path re-translated and rebuilt"
