#!/usr/bin/env bash
# Installs what wash needs, builds it, then runs the seed example (2D water in a
# box) end to end, the way a user would: translate it with `wash` into a CMake
# project, build that project, run it, and draw the result.
# Leaves out/ca_fluid_sim/: the generated project (project/), the translator's
# model (model.txt), a ParaView series, the final state (final.csv) and final.png.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2

example=examples/ca_fluid_sim/ca_fluid_sim.cpp
out=out/ca_fluid_sim
mkdir -p "$out"
build/bin/wash --dump-model "$example" > "$out/model.txt"
build/bin/wash --backend=openmp "$example" -o "$out/project"
cmake -S "$out/project" -B "$out/project/build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$out/project/build" -j2
"$out/project/build/ca_fluid_sim-openmp" ca_fluid_sim --out "$out" --output-every 100 --dump "$out/final.csv"
/usr/bin/python3 scripts/render.py "$out/final.csv" "$out/final.png" --at position \
  --box 17.1 9.3 --color density --title "ca_fluid_sim after 1000 steps (4032 particles)"
echo "quickstart: open $out/ca_fluid_sim.pvd in ParaView; picture: $out/final.png"
