#!/usr/bin/env bash
# The translator, the runtime and one small scene built under AddressSanitizer
# and UndefinedBehaviorSanitizer (build-sanitize/), then the translator's lit
# and unit tests, the runtime's unit tests and the seed's differential test
# (20 steps) run under them: a memory error or undefined behaviour fails the
# test that hit it. Run alone, after scripts/install-deps.sh; not yet part of
# scripts/test.sh (docs/architecture.md, "Sanitizers").
set -euo pipefail
cd "$(dirname "$0")/.."

build=${WASH_SANITIZE_BUILD:-build-sanitize}
# -O1: the sanitizers' cost, not the optimiser's, should bound the run time.
cmake -S . -B "$build" -DWASH_SANITIZE=address,undefined \
  -DCMAKE_BUILD_TYPE=None -DCMAKE_C_FLAGS="-O1 -g1" -DCMAKE_CXX_FLAGS="-O1 -g1"
cmake --build "$build" -j2 --target wash washModelTests washEmitTests \
  washFrontendTests wash_runtime_tests ca_fluid_sim-reference \
  ca_fluid_sim-serial ca_fluid_sim-openmp

# Leaks are not checked: the translator exits without freeing Clang's AST on
# purpose (clang -disable-free), and libgomp keeps its thread pool. User
# poisoning is off: LLVM's allocator headers, compiled into our code with
# ASan, poison the slabs that Debian's uninstrumented libclang-cpp then
# allocates from without unpoisoning (false use-after-poison reports).
export ASAN_OPTIONS=detect_leaks=0:allow_user_poisoning=0:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j2 \
  -R '^(translator-lit|translator-unit\.|translator-frontend\.|runtime\.)'
# The seed, translated by the sanitized translator, against its reference:
# 20 steps (the differential test's 300 take too long under the sanitizers).
bin=$(cd "$build/bin" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
(cd "$scratch" && bash "$OLDPWD/test/e2e/differential.sh" "$bin" ca_fluid_sim 20 serial openmp)
