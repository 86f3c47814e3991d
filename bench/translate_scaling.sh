#!/usr/bin/env bash
# translate_scaling.sh - translation time against kernel size.
#
# Generates kernels of n statements, else-if chains of n branches and binary
# expressions of n terms, translates each (serial backend, a real output
# folder) and prints one line a run: shape, n, wall seconds, exit status.
# The targets (docs/performance.md): 10,000 statements and 10,000 branches
# each under 10 s. Nothing is asserted: this is a benchmark.
#
# usage: bench/translate_scaling.sh [--build DIR] [--sizes "1000 10000"]
set -euo pipefail
build=build
sizes="1000 2000 4000 10000"
while [[ $# -gt 0 ]]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    *) echo "usage: $0 [--build DIR] [--sizes \"N...\"]" >&2; exit 2 ;;
  esac
done
wash=$build/bin/wash
[[ -x $wash ]] || { echo "no $wash: build the translator first" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

generate() { # shape n > file
  python3 - "$1" "$2" <<'PY'
import sys
shape, n = sys.argv[1], int(sys.argv[2])
print("#include <wash/wash.hpp>")
print("void u(wash::Particle &p) {")
print("  double x = p.get_density();")
if shape == "statements":
    for i in range(n):
        print("  x += p.get_mass() * %d;" % i)
    print("  p.set_density(x);")
elif shape == "else-if":
    print("  if (x < 0) p.set_mass(0);")
    for i in range(1, n):
        print("  else if (x < %d) p.set_mass(%d);" % (i, i))
else:
    print("  p.set_mass(" + " + ".join(["p.get_density()"] * n) + ");")
print("}")
print("int main() { wash::set_influence_radius(0.1); wash::add_update_kernel(&u);")
print("  wash::set_max_iterations(1); wash::start(); }")
PY
}

printf "%-12s %8s %8s %s\n" shape n wall_s exit
for shape in statements else-if binary; do
  for n in $sizes; do
    generate "$shape" "$n" > "$work/k.cpp"
    rm -rf "$work/out"
    start=$(date +%s.%N)
    set +e
    "$wash" --backend=serial -o "$work/out" "$work/k.cpp" 2> "$work/err"
    status=$?
    set -e
    end=$(date +%s.%N)
    printf "%-12s %8d %8.2f %d\n" "$shape" "$n" "$(echo "$end - $start" | bc)" "$status"
  done
done
