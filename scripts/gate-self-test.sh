#!/usr/bin/env bash
# End-to-end self-test of both CI gates against results/baselines/. Slow (it builds a second tree), so it is not part
# of scripts/test.sh; run it after changing a gate. The second tree is built with -DTCSB_INJECT_SLOWDOWN=ON: its
# TC-SB step becomes TCSB_INJECT_STEP_PERCENT % more expensive in what a run measures (src/case/case_body.cpp), a
# known fraction of the step rather than a fixed delay. Checks that `tcsb compare`
#   wall-time gate (suite ci, at CI's threshold):
#   1. does not fail an unchanged rerun of the ci suite (exit 0; exit 4, undecided, when the machine is too loaded
#      for its intervals to clear the threshold),
#   2. fails a build whose TC-SB step takes TCSB_GATE_TIME_PERCENT % longer (default 100) as a regression (exit 1),
#   3. fails a result whose first final-state hash was edited as changed behaviour       (exit 1),
#   4. refuses a run of a different suite (the ci suite with one more step)              (exit 2);
#   instruction gate (suite ci-instructions under callgrind, at its default 0.5 %):
#   5. passes an unchanged rerun                                                        (exit 0),
#   6. fails the same build with 1 % more instructions in each TC-SB step                (exit 1),
#   7. refuses to compare a time result with a count result                             (exit 2).
# Usage: bash scripts/gate-self-test.sh   (TCSB_BUILD_DIR, default build; the slowed tree is build-inject;
#        TCSB_GATE_THRESHOLD, default 0.10: keep it equal to the --threshold scripts/test.sh gates wall time with)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TCSB_BUILD_DIR:-build}
slowed=build-inject
baseline=results/baselines/ci.json
counts=results/baselines/ci-instructions.json
threshold=${TCSB_GATE_THRESHOLD:-0.10}
time_percent=${TCSB_GATE_TIME_PERCENT:-100}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target tcsb
cmake -S . -B "$slowed" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTCSB_INJECT_SLOWDOWN=ON -DTCSB_BUILD_TESTS=OFF \
      -DTCSB_BUILD_BENCH=OFF >/dev/null
cmake --build "$slowed" --target tcsb

failed=0
# expect CODES PATTERN DESCRIPTION BASE NEW [FLAGS...]: runs `tcsb compare BASE NEW FLAGS`, checks that the exit code
# is one of CODES (e.g. "0" or "0|4") and that the last stderr line matches PATTERN, and prints that line.
expect() {
  local want=$1 pattern=$2 what=$3 base=$4 next=$5 got
  shift 5
  set +e
  "$build/tcsb" compare "$@" "$base" "$next" >/dev/null 2>"$tmp/err"
  got=$?
  set -e
  local last
  last=$(tail -n 1 "$tmp/err")
  if grep -qxE -- "$want" <<<"$got" && grep -q -- "$pattern" <<<"$last"; then
    echo "gate-self-test: ok    $what: exit $got: $last"
  else
    echo "gate-self-test: FAIL  $what: exit $got (expected $want): $last"
    failed=1
  fi
}

"$build/tcsb" run ci --quiet --out "$tmp/rerun.json"
expect "0|4" "\(PASS\|UNDECIDED\): 0 regressions, 0 behaviour changes" "unchanged rerun" "$baseline" \
       "$tmp/rerun.json" --threshold "$threshold"

TCSB_INJECT_STEP_PERCENT=$time_percent "$slowed/tcsb" run ci --quiet --out "$tmp/slowed.json"
expect 1 "FAIL: [1-9][0-9]* regressions*, 0 behaviour changes" "TC-SB's step $time_percent % longer" \
       "$baseline" "$tmp/slowed.json" --threshold "$threshold"

sed '0,/"final_state_hash": "[0-9a-f]*"/s//"final_state_hash": "0000000000000000"/' "$tmp/rerun.json" \
  >"$tmp/edited.json"
expect 1 "FAIL: 0 regressions, 1 behaviour change" "one final-state hash edited" "$baseline" "$tmp/edited.json" \
       --threshold "$threshold"

sed 's/"steps": 200/"steps": 201/' suites/ci.json >"$tmp/ci-other.json"
"$build/tcsb" run "$tmp/ci-other.json" --quiet --out "$tmp/other.json"
expect 2 "different suites" "a different suite" "$baseline" "$tmp/other.json" --threshold "$threshold"

"$build/tcsb" run ci-instructions --measure instructions --quiet --out "$tmp/counts.json"
expect 0 "PASS: 0 regressions, 0 behaviour changes" "unchanged counts" "$counts" "$tmp/counts.json"

TCSB_INJECT_STEP_PERCENT=1 "$slowed/tcsb" run ci-instructions --measure instructions --quiet \
  --out "$tmp/counts-slowed.json"
expect 1 "FAIL: 12 regressions, 0 behaviour changes" "1 % more instructions per TC-SB step" \
       "$counts" "$tmp/counts-slowed.json"

set +e
"$build/tcsb" compare "$baseline" "$tmp/counts.json" >/dev/null 2>"$tmp/err"
got=$?
set -e
if [ "$got" = 2 ] && [ "$(wc -l <"$tmp/err")" = 1 ] && grep -q "cannot be compared" "$tmp/err"; then
  echo "gate-self-test: ok    a time result against a count result: exit 2: $(cat "$tmp/err")"
else
  echo "gate-self-test: FAIL  a time result against a count result: exit $got (expected 2): $(cat "$tmp/err")"
  failed=1
fi

exit "$failed"
