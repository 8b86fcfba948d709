#!/usr/bin/env bash
# Measures both CI gates' error rates on this machine, as docs/methodology.md ("The gates' error rates") reports them:
#   wall-time gate: the ci suite run K times on one build, every ordered pair of those runs compared (false
#     positives: an unchanged build called a regression; undecided counted apart), and each run of a build whose
#     TC-SB step is P % slower (-DTCSB_INJECT_SLOWDOWN=ON, TCSB_INJECT_STEP_PERCENT=P) compared against each unchanged
#     run (power: the slowdown called a regression), at each threshold in THRESHOLDS;
#   instruction gate: ci-instructions counted twice on one build and compared (false positives), and once with 1 %
#     more instructions per TC-SB step (power: TC-SB cases called regressions).
# Prints the machine's load (uptime) before and after, and one table row per gate, threshold and slowdown.
# Usage: bash scripts/gate-error-rates.sh [K] [SLOWED_RUNS]   (defaults 6 and 4; K runs give K (K - 1) ordered pairs)
#   TCSB_RATES_PERCENTS="5 10 25" slowdowns, TCSB_RATES_THRESHOLDS="0.05 0.1 0.25" wall-time thresholds,
#   TCSB_BUILD_DIR (default build) and build-inject (the slowed tree) as in scripts/gate-self-test.sh.
# Takes about K + 3 SLOWED_RUNS + 3 ci runs (half a minute each on the development VM).
set -euo pipefail
cd "$(dirname "$0")/.."
# Bad arguments: exit 2 and one line, before anything is built or run (0 runs built both trees and printed an empty
# table with exit 0).
bad() {
  echo "gate-error-rates: $1 (usage: bash scripts/gate-error-rates.sh [K] [SLOWED_RUNS], 2 <= K, 1 <= SLOWED_RUNS <= K)" >&2
  exit 2
}
(($# <= 2)) || bad "at most two arguments, got $#"
runs=${1:-6}
slowed_runs=${2:-4}
[[ $runs =~ ^[0-9]{1,4}$ ]] && ((10#$runs >= 2)) || bad "K must be a whole number of runs >= 2, got '$runs'"
runs=$((10#$runs))
[[ $slowed_runs =~ ^[0-9]{1,4}$ ]] && ((10#$slowed_runs >= 1 && 10#$slowed_runs <= runs)) ||
  bad "SLOWED_RUNS must be a whole number from 1 to K ($runs), got '$slowed_runs'"
slowed_runs=$((10#$slowed_runs))
percents=${TCSB_RATES_PERCENTS:-5 10 25}
thresholds=${TCSB_RATES_THRESHOLDS:-0.05 0.1 0.25}
[ -n "${percents// /}" ] || bad "TCSB_RATES_PERCENTS is empty"
for p in $percents; do
  [[ $p =~ ^[0-9]{1,3}$ ]] && ((10#$p >= 1)) || bad "TCSB_RATES_PERCENTS: a slowdown must be a whole percentage >= 1, got '$p'"
done
[ -n "${thresholds// /}" ] || bad "TCSB_RATES_THRESHOLDS is empty"
for t in $thresholds; do
  [[ $t =~ ^(0|[0-9]*\.[0-9]+|[1-9][0-9]*)$ ]] || bad "TCSB_RATES_THRESHOLDS: a threshold must be a number >= 0, got '$t'"
done
build=${TCSB_BUILD_DIR:-build}
slowed=build-inject
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target tcsb >&2
cmake -S . -B "$slowed" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTCSB_INJECT_SLOWDOWN=ON -DTCSB_BUILD_TESTS=OFF \
      -DTCSB_BUILD_BENCH=OFF >/dev/null
cmake --build "$slowed" --target tcsb >&2

echo "gate-error-rates: $(date -u +%FT%TZ), $("$build/tcsb" --version | head -n 1)"
echo "gate-error-rates: load before: $(uptime)"
# Unchanged and slowed runs interleave, so a change of the machine's load falls on both alike.
for ((i = 0; i < runs; ++i)); do
  "$build/tcsb" run ci --quiet --out "$tmp/same-$i.json" 2>/dev/null
  if ((i < slowed_runs)); then
    for p in $percents; do
      TCSB_INJECT_STEP_PERCENT=$p "$slowed/tcsb" run ci --quiet --out "$tmp/slow$p-$i.json" 2>/dev/null
    done
  fi
done

# verdicts THRESHOLD BASE... -- NEW...: "regressions undecided passes" over every (base, new) pair of distinct files.
verdicts() {
  local threshold=$1 regressed=0 undecided=0 passed=0 other=0 code
  shift
  local bases=() nexts=() seen=0
  for f in "$@"; do
    if [ "$f" = -- ]; then seen=1; continue; fi
    if [ $seen = 0 ]; then bases+=("$f"); else nexts+=("$f"); fi
  done
  for a in "${bases[@]}"; do
    for b in "${nexts[@]}"; do
      [ "$a" = "$b" ] && continue
      code=0
      "$build/tcsb" compare --threshold "$threshold" "$a" "$b" >/dev/null 2>&1 || code=$?
      case $code in 0) passed=$((passed + 1)) ;; 1) regressed=$((regressed + 1)) ;; 4) undecided=$((undecided + 1)) ;;
        *) other=$((other + 1)) ;; esac
    done
  done
  echo "$regressed $undecided $passed $other"
}

echo
echo "| gate | threshold | builds compared | pairs | regression (exit 1) | undecided (exit 4) | pass (exit 0) |"
echo "|---|---:|---|---:|---:|---:|---:|"
same=("$tmp"/same-*.json)
for t in $thresholds; do
  read -r r u p o <<<"$(verdicts "$t" "${same[@]}" -- "${same[@]}")"
  echo "| wall time | $t | unchanged vs unchanged | $((r + u + p + o)) | $r | $u | $p |"
  for pct in $percents; do
    slow=("$tmp"/slow$pct-*.json)
    read -r r u p o <<<"$(verdicts "$t" "${same[@]}" -- "${slow[@]}")"
    echo "| wall time | $t | unchanged vs TC-SB step +$pct % | $((r + u + p + o)) | $r | $u | $p |"
  done
done

"$build/tcsb" run ci-instructions --measure instructions --quiet --out "$tmp/counts-a.json" 2>/dev/null
"$build/tcsb" run ci-instructions --measure instructions --quiet --out "$tmp/counts-b.json" 2>/dev/null
TCSB_INJECT_STEP_PERCENT=1 "$slowed/tcsb" run ci-instructions --measure instructions --quiet \
  --out "$tmp/counts-1.json" 2>/dev/null
# Per case: a count result's cases are each gated, so the rates are over cases (TC-SB cases for power).
count_cases() {
  local code=0
  "$build/tcsb" compare --summary-json "$tmp/s.json" "$1" "$2" >/dev/null 2>&1 || code=$?
  python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); print(s["regressions"], s["gated"])' "$tmp/s.json"
}
read -r r g <<<"$(count_cases "$tmp/counts-a.json" "$tmp/counts-b.json")"
echo "| instructions | 0.005 | unchanged vs unchanged | $g cases | $r | – | $((g - r)) |"
read -r r g <<<"$(count_cases "$tmp/counts-a.json" "$tmp/counts-1.json")"
tcsb_cases=$(python3 -c 'import json, sys; print(sum(c["method"] == "tcsb" for c in json.load(open(sys.argv[1]))["cases"]))' \
  "$tmp/counts-a.json")
echo "| instructions | 0.005 | unchanged vs TC-SB step +1 % instructions | $tcsb_cases TC-SB cases | $r | – | $((tcsb_cases - r)) |"
echo
echo "gate-error-rates: load after: $(uptime)"
