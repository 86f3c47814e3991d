# wash installed to a prefix is usable as README.md says: a user project with
# headers of its own (the multi_file scene) finds it through
# CMAKE_PREFIX_PATH, is translated by the installed wash and its API headers
# (not this build tree), and computes the same dump as its reference build;
# wash_DIR=<prefix>/lib/cmake/wash finds it too. The project also uses wash's
# SPH library (a particle helper of wash/sph/diagnostics.hpp), which the
# installed wash rewrites from the installed headers. `wash run` from the
# prefix builds it against the installed package.
. "$(dirname "$0")/lib.sh"
build_dir=$1 scene_dir=$2

expect_exit 0 cmake --install "$build_dir" --prefix "$work/prefix"
[ -x prefix/bin/wash ] || fail "no wash in the installed prefix"
[ -f prefix/include/wash/wash.hpp ] || fail "no wash/wash.hpp in the installed prefix"
[ -f prefix/lib/cmake/wash/washConfig.cmake ] || fail "no washConfig.cmake in the installed prefix"
[ -f prefix/include/wash/sph/sph.hpp ] || fail "no wash/sph/sph.hpp in the installed prefix"

cp -r "$scene_dir" src
# The scene, with a Sum of the SPH library's kinetic energy.
sed -i -e 's|^#include <wash/wash.hpp>$|&\n#include <wash/sph/diagnostics.hpp>|' \
  -e 's|^void Spawn() {$|double Kinetic(const wash::Particle\& p) { return wash::sph::kinetic_energy(p); }\n\n&|' \
  -e 's|^    wash::start();$|    wash::add_variable("kinetic", 0.0);\n    wash::add_reduction_kernel(\&Kinetic, wash::Reduction::Sum, "kinetic");\n&|' \
  src/multi_file.cpp
[ "$(grep -c 'kinetic' src/multi_file.cpp)" = 3 ] || fail "could not add the SPH library to the scene"
cat > src/CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(installed_wash LANGUAGES CXX)
find_package(wash REQUIRED CONFIG)
wash_add_simulation(sim SOURCE multi_file.cpp BACKEND serial INCLUDE_DIRECTORIES include)
wash_add_reference(sim-reference SOURCE multi_file.cpp DIM 2 INCLUDE_DIRECTORIES include)
CMAKE

expect_exit 0 cmake -S src -B bld -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix"
grep -qF "$work/prefix/bin/wash" bld/build.ninja || fail "the project does not translate with the installed wash"
expect_exit 0 cmake --build bld
grep -qF "$build_dir" bld/sim.wash/multi_file.serial.cpp bld/sim.wash/user/scene/walls.hpp &&
  fail "the installed wash generated code that names its build tree"
grep -qF "#line 1 \"$work/prefix/include/wash/sph/diagnostics.hpp\"" bld/sim.wash/user/wash/sph/diagnostics.hpp ||
  fail "wash/sph/diagnostics.hpp was not rewritten from the installed prefix"
grep -qF "wash_gen::" bld/sim.wash/user/wash/sph/diagnostics.hpp ||
  fail "the SPH library's particle helper was not rewritten"
expect_exit 0 bld/sim-reference --steps 50 --quiet --dump reference.csv --out ref
expect_exit 0 bld/sim --steps 50 --quiet --dump serial.csv --out ser
cmp -s reference.csv serial.csv || fail "the installed wash's program differs from the reference: $(cmp reference.csv serial.csv)"

# wash run from the prefix builds against the installed package.
export XDG_CACHE_HOME="$work/cache"
expect_exit 0 prefix/bin/wash run -I src/include src/multi_file.cpp -- --steps 50 --quiet --dump run.csv --out run
cmp -s reference.csv run.csv || fail "wash run of the installed wash differs from the reference: $(cmp reference.csv run.csv)"
grep -qxF "wash_DIR:PATH=$work/prefix/lib/cmake/wash" cache/wash/multi_file-serial-*/build/CMakeCache.txt ||
  fail "wash run from the prefix did not build against the installed package"

# wash_DIR names the package folder itself.
expect_exit 0 cmake -S src -B bld2 -G Ninja -Dwash_DIR="$work/prefix/lib/cmake/wash"
grep -qF "$work/prefix/bin/wash" bld2/build.ninja || fail "wash_DIR did not select the installed wash"
echo "installed wash: a project with its own headers and wash/sph builds against the prefix and matches its reference"
