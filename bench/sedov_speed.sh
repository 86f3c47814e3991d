#!/usr/bin/env bash
# sedov_speed.sh - the Sedov scene's speed against an older build (issue 22).
#
# Runs examples/sedov (the serial program, one thread) at each lattice size
# (n^3 particles) for S steps, with the OLD build's program and this build's
# interleaved: each round runs both at every size, the order of the two
# alternating from round to round, so that the machine's drift hits both
# alike. Prints per size the fastest round of each program's own "ns per
# particle-step" (the steps alone: start-up and frames excluded), the ratio
# new/old of those, and the median of the rounds' own ratios; then the same
# from the CPU time each run took (user + system, /usr/bin/time: the whole
# run, start-up included), which a machine loaded by other work disturbs
# less than the wall clock the programs time. Below 1: the current build is
# faster. On a loaded machine compare the ratios only.
#
# usage: bench/sedov_speed.sh --old OLD_BUILD [--new NEW_BUILD] [--sizes "30 50"]
#                             [--steps S] [--rounds R]
#   --old DIR     the build to compare against (its bin/sedov-serial)
#   --new DIR     the build measured (default: this tree's build/)
#   --sizes LIST  lattice sizes n (default "30 50")
#   --steps S     steps per run (default 21)
#   --rounds R    rounds (default 3)
# Nothing is asserted: speed is measured, never tested.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
old=""
new=$root/build
sizes="30 50"
steps=21
rounds=3
die() { echo "sedov_speed.sh: $*" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case $1 in
    --old) old=$2; shift 2 ;;
    --new) new=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
done
[[ -n $old ]] || die "no --old build given (see --help)"
for n in $sizes "$steps" "$rounds"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || die "expected a positive integer, got '$n'"
done
declare -A program=([old]=$old/bin/sedov-serial [new]=$new/bin/sedov-serial)
for b in old new; do
  [[ -x ${program[$b]} ]] || die "no ${program[$b]} (build the sedov-serial target)"
done

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# "wall cpu": ns per particle-step of one run of build $1 at size $2, by the
# program's own timer (the steps alone) and by the CPU time of the whole run.
measure() {
  local line cpu
  line=$(OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive /usr/bin/time -f '%U %S' -o "$out/time" \
           "${program[$1]}" "$2" --steps "$steps" --out "$out/$1" 2>&1 |
           grep -o '[0-9.]* ns per particle-step' || true)
  [[ -n $line ]] || die "${program[$1]} $2 printed no 'ns per particle-step' (it failed?)"
  cpu=$(awk -v n="$2" -v s="$steps" '{ printf "%.1f", ($1 + $2) * 1e9 / (n * n * n * s) }' "$out/time")
  echo "${line%% *} $cpu"
}
# Keeps the smaller of $2 and best[$1].
keepBest() {
  if [[ -z ${best[$1]:-} ]] || awk -v a="$2" -v b="${best[$1]}" 'BEGIN { exit !(a < b) }'; then
    best[$1]=$2
  fi
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.4f", a / b }'; }
median() {
  tr ' ' '\n' <<<"$1" | grep . | sort -g |
    awk '{ v[NR] = $1 } END { printf "%.3f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

declare -A best=() ratios=()
for ((r = 1; r <= rounds; ++r)); do
  order="old new"
  ((r % 2 == 0)) && order="new old"
  for n in $sizes; do
    declare -A wall=() cpu=()
    for b in $order; do
      read -r wall[$b] cpu[$b] < <(measure "$b" "$n")
      keepBest "wall,$b,$n" "${wall[$b]}"
      keepBest "cpu,$b,$n" "${cpu[$b]}"
    done
    ratios[wall,$n]+="$(ratio "${wall[new]}" "${wall[old]}") "
    ratios[cpu,$n]+="$(ratio "${cpu[new]}" "${cpu[old]}") "
    echo "round $r, n = $n: ns per particle-step old ${wall[old]} (cpu ${cpu[old]})," \
         "new ${wall[new]} (cpu ${cpu[new]})" >&2
    unset wall cpu
  done
done

printf '%-5s %-9s %-6s %-10s %-10s %-8s %s\n' "n" "particles" "timer" "old ns" "new ns" \
  "new/old" "median of the rounds' new/old"
for n in $sizes; do
  for t in wall cpu; do
    printf '%-5s %-9s %-6s %-10s %-10s %-8s %s\n' "$n" "$((n * n * n))" "$t" "${best[$t,old,$n]}" \
      "${best[$t,new,$n]}" "$(ratio "${best[$t,new,$n]}" "${best[$t,old,$n]}" | cut -c1-5)" \
      "$(median "${ratios[$t,$n]}")"
  done
done
