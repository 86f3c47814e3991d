# Other compilers compute the same bits: the seed (examples/ca_fluid_sim) and
# a float-storage scene (scenes/float_store.cpp), translated for the serial
# backend, built by a project configured against this build of wash with
# clang++ at -O3 and with this build's compiler at -O0, must write the same
# --dump as this build's own programs (g++ -O3 in CI), byte for byte.
#   cross_compiler.sh PACKAGE_DIR BIN CLANGXX CXX SEED_SOURCE FLOAT_SOURCE
. "$(dirname "$0")/lib.sh"
package_dir=$1 bin=$2 clangxx=$3 cxx=$4 seed=$5 float_scene=$6

mkdir src
cp "$seed" src/seed.cpp
cp "$float_scene" src/float_store.cpp
cat > src/CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(cross_compiler LANGUAGES CXX)
find_package(wash REQUIRED CONFIG)
wash_add_simulation(seed SOURCE seed.cpp BACKEND serial)
wash_add_simulation(float_store SOURCE float_store.cpp BACKEND serial)
CMAKE

# The dumps of this build's programs: what every other build must write.
expect_exit 0 "$bin/ca_fluid_sim-serial" --steps 100 --quiet --dump seed.csv --out o
expect_exit 0 "$bin/float_store-serial" --quiet --dump float_store.csv --out o

# check NAME CMAKE-ARGS...: configure, build and compare both programs.
check() {
  local name=$1
  shift
  expect_exit 0 cmake -S src -B "$name" -G Ninja -Dwash_DIR="$package_dir" "$@"
  expect_exit 0 cmake --build "$name"
  expect_exit 0 "$name/seed" --steps 100 --quiet --dump "$name-seed.csv" --out o
  expect_exit 0 "$name/float_store" --quiet --dump "$name-float_store.csv" --out o
  for scene in seed float_store; do
    cmp -s "$scene.csv" "$name-$scene.csv" ||
      fail "$scene built with $name differs from this build's program: $(cmp "$scene.csv" "$name-$scene.csv")"
  done
}
# wash's package finds OpenMP, which clang++ may lack (no libomp): only serial
# programs are built here, so g++'s libgomp stands in.
check clang-O3 -DCMAKE_CXX_COMPILER="$clangxx" -DCMAKE_BUILD_TYPE=Release \
  -DOpenMP_CXX_FLAGS=-fopenmp=libgomp -DOpenMP_CXX_LIB_NAMES=gomp \
  -DOpenMP_gomp_LIBRARY="$("$cxx" -print-file-name=libgomp.so)"
check cxx-O0 -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE= -DCMAKE_CXX_FLAGS=-O0
grep -q -- "-O0" cxx-O0/build.ninja || fail "the -O0 build was not built at -O0"
echo "cross compiler: seed and float_store identical with $clangxx -O3 and $cxx -O0"
