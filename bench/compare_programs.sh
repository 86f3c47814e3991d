#!/usr/bin/env bash
# compare_programs.sh - A/B timing of programs that run the same scene.
#
# Runs every program given once per round, rounds interleaved (so that the
# VM's drift hits all programs alike), and prints for each the fastest of the
# rounds of its own "ns per particle-step" (the steps alone: start-up and
# frames excluded; every wash program, generated or hand-written, prints it in
# its summary line), and its ratio to the first program.
#
# A difference of a few per cent between two *different binaries* is not
# evidence on its own: moving the neighbour scan's inner loop by 16 bytes moves
# the whole seed program by ~6 % (docs/performance.md). Compare builds of one
# source at several -falign-loops values when it matters.
#
# usage: bench/compare_programs.sh [--rounds R] [--steps S] [--threads T] PROGRAM...
#   --rounds R    rounds (default 3)
#   --steps S     steps per run (default 600)
#   --threads T   OMP_NUM_THREADS for every run (default 1)
# Nothing is asserted: speed is measured, never tested.
set -euo pipefail

rounds=3
steps=600
threads=1
die() { echo "compare_programs.sh: $*" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case $1 in
    --rounds) rounds=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) die "unknown option '$1' (see --help)" ;;
    *) break ;;
  esac
done
[[ $# -ge 1 ]] || die "no program given (see --help)"
for n in "$rounds" "$steps" "$threads"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || die "expected a positive integer, got '$n'"
done

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
declare -A best=()
for ((r = 1; r <= rounds; ++r)); do
  for p in "$@"; do
    line=$(OMP_NUM_THREADS=$threads OMP_WAIT_POLICY=passive "$p" --steps "$steps" --out "$out" 2>&1 |
           grep -o '[0-9.]* ns per particle-step' || true)
    [[ -n $line ]] || die "$p printed no 'ns per particle-step' (not a wash program, or it failed)"
    v=${line%% *}
    if [[ -z ${best[$p]:-} ]] || awk -v a="$v" -v b="${best[$p]}" 'BEGIN { exit !(a < b) }'; then
      best[$p]=$v
    fi
  done
done
first=${best[$1]}
printf '%-12s %-8s %s\n' "ns/p-step" "ratio" "program"
for p in "$@"; do
  printf '%-12s %-8s %s\n' "${best[$p]}" "$(awk -v a="${best[$p]}" -v b="$first" 'BEGIN { printf "%.3f", a / b }')" "$p"
done
