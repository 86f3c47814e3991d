#!/usr/bin/env bash
# Binary (default) against ASCII VTK frames, side by side in one run: bytes
# per frame and the seconds the run spends outside its steps (start-up and
# writing frames), for PROGRAM writing a frame after every one of STEPS steps.
#   bash bench/vtk_encoding.sh PROGRAM [STEPS] [program arguments...]
# e.g. OMP_NUM_THREADS=1 bash bench/vtk_encoding.sh build/bin/sedov-openmp 4 30
set -euo pipefail
program=$1 steps=${2:-4}
shift 2 || shift $#
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A bytes output
for round in 1 2 3; do
  for enc in binary ascii; do
    line=$("$program" "$@" --steps "$steps" --output-every 1 --vtk-encoding "$enc" \
      --out "$work/$enc" | tail -n 1)
    total=$(sed -E 's/.* in ([0-9.]+) s .*/\1/' <<<"$line")
    alone=$(sed -E 's/.*steps alone ([0-9.]+) s.*/\1/' <<<"$line")
    output[$enc]="${output[$enc]:-} $(awk -v a="$total" -v b="$alone" 'BEGIN { print a - b }')"
    bytes[$enc]=$(cat "$work/$enc"/*.vtp | wc -c)
    rm -rf "${work:?}/$enc"
  done
done
best() { tr ' ' '\n' <<<"$1" | grep . | sort -g | head -n 1; }
b=$(best "${output[binary]}") a=$(best "${output[ascii]}")
echo "frames: $((steps + 1)); bytes binary ${bytes[binary]}, ascii ${bytes[ascii]}," \
  "ratio ascii/binary $(awk -v a="${bytes[ascii]}" -v b="${bytes[binary]}" 'BEGIN { printf "%.2f", a / b }')"
echo "seconds outside the steps (best of 3): binary $b, ascii $a," \
  "ratio ascii/binary $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }')"
