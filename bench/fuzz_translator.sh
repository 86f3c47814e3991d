#!/usr/bin/env bash
# fuzz_translator.sh - a bounded fuzzing run of the translator's front end.
#
# With AFL++ installed (Debian package afl++): afl-fuzz in non-instrumented
# mode (-n) on the wash binary, seeded with the examples, for --seconds;
# a hang is a run over 20 s;
# crashes and hangs land in DIR/afl/default/{crashes,hangs}. Without it (this
# project's machines have neither AFL++ nor a libFuzzer runtime for clang
# 19): rounds of the mutation corpus (test/translator/corpus/mutate.py) with
# fresh seeds until --seconds are spent; every problem is printed. Nothing
# is asserted: this is a benchmark; see docs/performance.md for results.
#
# usage: bench/fuzz_translator.sh [--build DIR] [--seconds S] [--out DIR]
set -euo pipefail
build=build
seconds=300
out=$(mktemp -d)
while [[ $# -gt 0 ]]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "usage: $0 [--build DIR] [--seconds S] [--out DIR]" >&2; exit 2 ;;
  esac
done
src=$(cd "$(dirname "$0")/.." && pwd)
wash=$(cd "$build" && pwd)/bin/wash
[[ -x $wash ]] || { echo "no $wash: build the translator first" >&2; exit 1; }
mkdir -p "$out"
# The std headers precompiled once (as the mutation corpus does): a run then
# takes about half the time, most of which was parsing them.
pch_args=()
pch=$(python3 -c 'import sys; sys.path.insert(0, sys.argv[1]); import mutate
print(mutate.precompile(sys.argv[2], sys.argv[3], sys.argv[4]) or "")' \
  "$src/test/translator/corpus" /usr/lib/llvm-19/bin/clang++ "$src/runtime/include" "$out" || true)
[[ -n $pch ]] && pch_args=(-- -include-pch "$pch")

if command -v afl-fuzz > /dev/null; then
  mkdir -p "$out/seeds"
  cp "$src"/examples/*/*.cpp "$out/seeds/"
  AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 \
    timeout "$seconds" afl-fuzz -n -t 20000 -i "$out/seeds" -o "$out/afl" -- \
    "$wash" --dump-model @@ "${pch_args[@]}" || true
  # AFL++ 4.04 writes its findings in -o itself; later versions in -o/default.
  results=$out/afl
  [[ -d $results/default ]] && results=$results/default
  echo "executions: $(tail -n 1 "$results/plot_data" 2>/dev/null | cut -d, -f12 | tr -d ' ')"
  echo "crashes: $(find "$results/crashes" -type f ! -name README.txt 2>/dev/null | wc -l)"
  echo "hangs: $(find "$results/hangs" -type f 2>/dev/null | wc -l)"
  exit 0
fi

echo "afl-fuzz not found: rounds of the mutation corpus for $seconds s"
end=$(( $(date +%s) + seconds ))
round=0
while (( $(date +%s) < end )); do
  round=$((round + 1))
  seed=$(( 1000 + round ))
  python3 "$src/test/translator/corpus/mutate.py" --wash "$wash" --examples "$src/examples" \
    --count 56 --seed "$seed" --keep "$out/round-$round" --clang /usr/lib/llvm-19/bin/clang++ |
    tail -n 20 || true
done
echo "$round rounds of 56 mutants; the mutants are in $out"
