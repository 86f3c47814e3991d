#!/usr/bin/env bash
# run_bench.sh - speed of the seed simulation's builds, in one table.
#
# Runs, at each size, the reference build, the hand-written baseline
# (bench/handwritten) at each thread count, and any further programs given
# (e.g. the translator's build/bin/ca_fluid_sim-serial and -openmp), on the seed
# scene scaled to that many particles at the same density, and prints:
#
#   size, program, threads, steps, wall s, ns per particle-step, ratio to the
#   hand-written serial run at that size, peak RSS per particle (bytes)
#
# Measurement: "ns/p-step" is the cost of a step once running: that of S
# steps less that of B (B = --base-steps, default 1), per particle and step.
# Every wash program (generated or hand-written) times its own step loop and
# prints it ("... ns per particle-step" in its summary line), so start-up,
# spawn and output, and their disk noise, are out of it; B takes out the
# first step's one-off work (first touch of the columns, the first sort from
# spawn order), which 20 steps at 1M particles would otherwise count at a
# twentieth:
#   (own(S) * S - own(B) * B) / (S - B)
# each the minimum of --repeat runs. For a program that prints none (a
# reference build older than the shared run set-up) it is the wall time of
# the whole process (date +%s%N around it, minimum of --repeat runs):
#   (wall(S steps) - wall(B steps)) / (N * (S - B))
# (B = 0 there would leave in the difference between writing the final frame
# after steps, 17 significant digits a value, and after none, mostly "0": at
# 1M particles over a second, which 20 steps would count as 60 ns per
# particle-step.)
# "wall s" is the S-step run as it is. Peak RSS comes from /usr/bin/time -f %M (GNU time) when installed.
# Nothing here is asserted: speed is measured, never tested.
#
# Which binary runs at size N: for the seed size 4032, the program as given;
# for another N, the same name with "ca_fluid_sim" replaced by "ca_fluid_sim_N"
# (bench/CMakeLists.txt builds ca_fluid_sim_N-reference from
# bench/scenes/make_scaled_seed.sh; translated builds of the same sources
# follow the same naming). The hand-written program takes --size N instead.
# A binary that does not exist gives a "not built" row.
#
# usage: bench/run_bench.sh [options]
#   --bin DIR              where the programs are (default: build/bin)
#   --sizes "N ..."        particle counts (default: "4032 65536")
#   --with-1m              also run 1048576 particles (few steps)
#   --threads "T ..."      OpenMP thread counts (default: "1 2")
#   --steps S              steps at every size (default: 1000 at <= 4032,
#                          200 at <= 65536, 10 above)
#   --steps-for N:S        steps at size N only (repeatable)
#   --repeat R             rounds of every run, interleaved; minimum taken
#                          (default 1)
#   --base-steps B         steps of the run subtracted (default 1, see above)
#   --program PATH         a further program run at every thread count
#                          (OMP_NUM_THREADS), e.g. build/bin/ca_fluid_sim-openmp
#   --serial-program PATH  a further program run once, threads 1,
#                          e.g. build/bin/ca_fluid_sim-serial
#   --no-reference         skip the reference build (slow at large sizes)
#   --csv FILE             also write the table as CSV
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bin=$here/../build/bin
sizes="4032 65536"
threads_list="1 2"
steps_all=""
declare -A steps_for=()
repeat=1
base_steps=1
with_ref=1
csv=""
parallel_programs=()
serial_programs=()

die() { echo "run_bench.sh: $*" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --with-1m) sizes="$sizes 1048576"; shift ;;
    --threads) threads_list=$2; shift 2 ;;
    --steps) steps_all=$2; shift 2 ;;
    --steps-for) [[ $2 =~ ^([0-9]+):([0-9]+)$ ]] || die "--steps-for expects N:S, got '$2'"
                 steps_for[${BASH_REMATCH[1]}]=${BASH_REMATCH[2]}; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --base-steps) base_steps=$2; shift 2 ;;
    --program) parallel_programs+=("$2"); shift 2 ;;
    --serial-program) serial_programs+=("$2"); shift 2 ;;
    --no-reference) with_ref=0; shift ;;
    --csv) csv=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option '$1' (see --help)" ;;
  esac
done
[[ $repeat =~ ^[1-9][0-9]*$ ]] || die "--repeat expects a positive integer"
[[ $base_steps =~ ^[0-9]+$ ]] || die "--base-steps expects a count of steps"

have_time=0
if [[ -x /usr/bin/time ]] && /usr/bin/time -f %M -o /dev/null true 2>/dev/null; then
  have_time=1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

steps_at() {
  local n=$1
  if [[ -n ${steps_for[$n]:-} ]]; then echo "${steps_for[$n]}"
  elif [[ -n $steps_all ]]; then echo "$steps_all"
  elif (( n <= 4032 )); then echo 1000
  elif (( n <= 65536 )); then echo 200
  else echo 10; fi
}

# binary_at PATH N: the program for size N (see the header).
binary_at() {
  local path=$1 n=$2
  if (( n == 4032 )); then echo "$path"; return; fi
  local dir base
  dir=$(dirname "$path")
  base=$(basename "$path")
  echo "$dir/${base/ca_fluid_sim/ca_fluid_sim_$n}"
}

# measure THREADS STEPS CMD...: one run; prints "wall_s rss_kb own_ns" (the
# "ns per particle-step" the program printed, or "-"), or "failed".
measure() {
  local threads=$1 steps=$2
  shift 2
  rm -rf "$work/out"
  local t0 t1 status=0
  t0=$(date +%s%N)
  if (( have_time )); then
    OMP_NUM_THREADS=$threads /usr/bin/time -f %M -o "$work/rss" \
      "$@" --steps "$steps" --out "$work/out" >"$work/log" 2>"$work/err" || status=$?
  else
    OMP_NUM_THREADS=$threads "$@" --steps "$steps" --out "$work/out" \
      >"$work/log" 2>"$work/err" || status=$?
  fi
  t1=$(date +%s%N)
  if (( status != 0 )); then
    echo "run_bench.sh: '$*' --steps $steps failed (status $status):" >&2
    tail -n 5 "$work/log" "$work/err" >&2
    echo "failed"
    return
  fi
  local own rss="-"
  own=$(grep -o '[0-9.]* ns per particle-step' "$work/log" || true)
  own=${own%% *}
  (( have_time )) && rss=$(tail -n 1 "$work/rss")
  echo "$(( t1 - t0 )) $rss ${own:--}"
}

# lower KEY VALUE / higher KEY VALUE: keep the least / greatest value of
# best[KEY] over the rounds ("-" counts as none).
declare -A best=()
lower() {
  [[ $2 == - ]] && return
  if [[ -z ${best[$1]:-} ]] || awk -v a="$2" -v b="${best[$1]}" 'BEGIN { exit !(a < b) }'; then
    best[$1]=$2
  fi
}
higher() {
  [[ $2 == - ]] && return
  if [[ -z ${best[$1]:-} ]] || (( $2 > best[$1] )); then best[$1]=$2; fi
}

# The runs, --repeat rounds of every configuration in turn (so that the
# VM's drift over minutes hits every program alike), each round one run of S
# steps and one of B. Configuration c is configs[c] = "size|label|threads"
# and its command cmd_c (an array).
configs=()
add_config() { # SIZE LABEL THREADS CMD...
  local c=${#configs[@]}
  configs+=("$1|$2|$3")
  shift 3
  eval "cmd_$c=(\"\$@\")"
}
run_config() { # C: one round of configuration C
  local c=$1 n label threads steps wall rss own
  IFS='|' read -r n label threads <<<"${configs[$c]}"
  local -n cmd="cmd_$c"
  steps=$(steps_at "$n")
  [[ -x ${cmd[0]} && -z ${best[$c.failed]:-} ]] || return 0
  echo "  $label, $n particles, $threads thread(s), $steps steps ..." >&2
  read -r wall rss own <<<"$(measure "$threads" "$steps" "${cmd[@]}")"
  if [[ $wall == failed ]]; then best[$c.failed]=1; return 0; fi
  lower "$c.wall" "$wall"; higher "$c.rss" "$rss"; lower "$c.own" "$own"
  if (( steps > base_steps )); then
    read -r wall rss own <<<"$(measure "$threads" "$base_steps" "${cmd[@]}")"
    [[ $wall == failed ]] && return 0
    lower "$c.wall0" "$wall"; lower "$c.own0" "$own"
  fi
}

echo "run_bench.sh: $(nproc) CPUs, sizes: $sizes, threads: $threads_list, repeat $repeat" >&2
for n in $sizes; do
  if (( with_ref )); then
    ref=$(binary_at "$bin/ca_fluid_sim-reference" "$n")
    add_config "$n" "$(basename "$ref")" 1 "$ref"
  fi
  for t in $threads_list; do
    add_config "$n" "ca_fluid_sim-handwritten" "$t" "$bin/ca_fluid_sim-handwritten" --size "$n"
  done
  for p in "${serial_programs[@]+"${serial_programs[@]}"}"; do
    b=$(binary_at "$p" "$n")
    add_config "$n" "$(basename "$b")" 1 "$b"
  done
  for p in "${parallel_programs[@]+"${parallel_programs[@]}"}"; do
    b=$(binary_at "$p" "$n")
    for t in $threads_list; do
      add_config "$n" "$(basename "$b")" "$t" "$b"
    done
  done
done
for ((round = 0; round < repeat; round++)); do
  for c in "${!configs[@]}"; do
    run_config "$c"
  done
done

rows=() # size|program|threads|steps|wall|ns|rss_kb
for c in "${!configs[@]}"; do
  IFS='|' read -r n label threads <<<"${configs[$c]}"
  unset -n cmd
  declare -n cmd="cmd_$c"
  steps=$(steps_at "$n")
  if [[ ! -x ${cmd[0]} ]]; then
    rows+=("$n|$label|$threads|$steps|not built|-|-")
    continue
  fi
  if [[ -n ${best[$c.failed]:-} || -z ${best[$c.wall]:-} ]]; then
    rows+=("$n|$label|$threads|$steps|failed|-|-")
    continue
  fi
  wall=$(awk -v ns="${best[$c.wall]}" 'BEGIN { printf "%.4f", ns / 1e9 }')
  own=${best[$c.own]:--} own0=${best[$c.own0]:--} wall0=${best[$c.wall0]:--}
  ns="-"
  if (( steps > base_steps )); then
    if [[ $own != - && ( $own0 != - || $base_steps == 0 ) ]]; then
      [[ $own0 == - ]] && own0=0
      ns=$(awk -v a="$own" -v a0="$own0" -v s="$steps" -v b="$base_steps" \
        'BEGIN { printf "%.1f", (a * s - a0 * b) / (s - b) }')
    elif [[ $wall0 != - ]]; then
      ns=$(awk -v w="${best[$c.wall]}" -v w0="$wall0" -v n="$n" -v s="$((steps - base_steps))" \
        'BEGIN { printf "%.1f", (w - w0) / (n * s) }')
    fi
  fi
  rows+=("$n|$label|$threads|$steps|$wall|$ns|${best[$c.rss]:--}")
done

# The table, with the ratio to the hand-written serial run at the same size.
declare -A base=()
for row in "${rows[@]}"; do
  IFS='|' read -r n label t steps wall ns rss <<<"$row"
  if [[ $label == ca_fluid_sim-handwritten && $t == 1 && $ns != - ]]; then base[$n]=$ns; fi
done
fmt="%-9s %-34s %7s %6s %10s %12s %9s %12s\n"
printf "$fmt" size program threads steps "wall s" "ns/p-step" ratio "RSS B/part"
[[ -n $csv ]] && echo "size,program,threads,steps,wall_s,ns_per_particle_step,ratio_to_handwritten_serial,peak_rss_bytes_per_particle" >"$csv"
for row in "${rows[@]}"; do
  IFS='|' read -r n label t steps wall ns rss <<<"$row"
  ratio="-"
  if [[ $ns != - && -n ${base[$n]:-} ]]; then
    ratio=$(awk -v a="$ns" -v b="${base[$n]}" 'BEGIN { printf "%.2f", a / b }')
  fi
  per="-"
  if [[ $rss != - ]]; then per=$(awk -v kb="$rss" -v n="$n" 'BEGIN { printf "%.0f", kb * 1024 / n }'); fi
  printf "$fmt" "$n" "$label" "$t" "$steps" "$wall" "$ns" "$ratio" "$per"
  [[ -n $csv ]] && echo "$n,$label,$t,$steps,$wall,$ns,$ratio,$per" >>"$csv"
done
if (( ! have_time )); then
  echo "(peak RSS not measured: GNU time is not installed at /usr/bin/time)"
fi
echo "(ns/p-step = steps B+1..S of the program's own timing of its steps; for a program that prints none, (wall of S steps - wall of B steps) / (particles * (S - B)); B = $base_steps; ratio = ns/p-step over the hand-written program's with 1 thread)"
