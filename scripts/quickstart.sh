#!/usr/bin/env bash
# Installs what wash needs, builds it, then runs the seed example (2D water in a
# box) end to end, the way a user would: translate, build and run it with one
# `wash run` (the build is cached in ~/.cache/wash), and draw the result.
# Leaves out/ca_fluid_sim/: the translator's model (model.txt), a ParaView
# series, the final state (final.csv) and final.png.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2

example=examples/ca_fluid_sim/ca_fluid_sim.cpp
out=out/ca_fluid_sim
mkdir -p "$out"
build/bin/wash --dump-model "$example" > "$out/model.txt"
build/bin/wash run --backend=openmp "$example" -- ca_fluid_sim --out "$out" --output-every 100 \
  --dump "$out/final.csv"
/usr/bin/python3 scripts/render.py "$out/final.csv" "$out/final.png" --at position \
  --box 17.1 9.3 --color density --title "ca_fluid_sim after 1000 steps (4032 particles)"
echo "quickstart: open $out/ca_fluid_sim.pvd in ParaView; picture: $out/final.png"
