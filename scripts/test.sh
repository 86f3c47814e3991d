#!/usr/bin/env bash
# Installs what wash needs, builds everything and runs every test (unit, lit,
# end-to-end) through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
ctest --test-dir build --output-on-failure -j2
