#!/usr/bin/env bash
# Installs what wash needs, builds it, then runs the seed example (2D water in a
# box) end to end: analyse it with the translator, run it, and draw the result.
# Leaves out/ca_fluid_sim/ (ParaView series, final state as CSV) and
# out/ca_fluid_sim/final.png.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2

example=examples/ca_fluid_sim/ca_fluid_sim.cpp
out=out/ca_fluid_sim
mkdir -p "$out"
if [ -x build/bin/wash ]; then
  build/bin/wash --dump-model "$example" > "$out/model.txt"
  echo "quickstart: the translator's model of $example is in $out/model.txt"
fi
build/bin/ca_fluid_sim-reference --out "$out" --output-every 100 --dump "$out/final.csv"
/usr/bin/python3 scripts/render.py "$out/final.csv" "$out/final.png" --at position \
  --box 17.1 9.3 --color density --title "ca_fluid_sim after 1000 steps (4032 particles)"
echo "quickstart: open $out/ca_fluid_sim.pvd in ParaView; picture: $out/final.png"
