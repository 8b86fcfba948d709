#!/usr/bin/env bash
# The scripts answer bad arguments and bad input files with exit 2 and one line on stderr, before they build, run or
# draw anything (issue 60): render-figures.py (--check on a kept run cut short, --animate without matplotlib or with a
# file that is not frames or world frames without their bodies, unknown arguments), error-concentration.py (malformed points, bad flags) and
# gate-error-rates.sh (run counts and environment settings it cannot use; a fake cmake first on PATH makes a script
# that would build fail at once instead). Needs python3 only. Usage: bash scripts/scripts-bad-input-self-test.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0

# expect_exit_2 WHAT NEEDLE COMMAND...: exit 2, exactly one line on stderr, containing NEEDLE.
expect_exit_2() {
  local what=$1 needle=$2 status=0
  shift 2
  "$@" >"$scratch/out" 2>"$scratch/err" || status=$?
  local lines
  lines=$(wc -l <"$scratch/err")
  if [[ $status != 2 || $lines != 1 ]] || ! grep -qF -- "$needle" "$scratch/err"; then
    echo "scripts-bad-input-self-test: FAIL: $what: exit $status, $lines line(s) on stderr, expected 2 and one line" \
      "with '$needle':" >&2
    head -n 5 "$scratch/err" >&2
    failures=$((failures + 1))
    return 0
  fi
  echo "scripts-bad-input-self-test: ok    $what: $(cat "$scratch/err")"
}

# ---- render-figures.py --------------------------------------------------------------------------------------------
mkdir -p "$scratch/tree/scripts" "$scratch/tree/results"
cp "$root/scripts/render-figures.py" "$scratch/tree/scripts/"
cp -r "$root/results/runs" "$root/results/figures" "$scratch/tree/results/"
kept=$(cd "$scratch/tree" && ls results/runs/*.json | sort -r | head -n 1)
head -c 300 "$root/$kept" >"$scratch/tree/$kept"  # a kept run cut short
expect_exit_2 "render-figures --check, a kept run cut short" "$kept" \
  env TCSB_FIGURES_ROOT="$scratch/tree" python3 "$scratch/tree/scripts/render-figures.py" --check
echo '[1, 2]' >"$scratch/tree/$kept"
expect_exit_2 "render-figures --check, a kept run that is not an object" "$kept" \
  env TCSB_FIGURES_ROOT="$scratch/tree" python3 "$scratch/tree/scripts/render-figures.py" --check

mkdir -p "$scratch/no-matplotlib/matplotlib"
echo 'raise ImportError("no matplotlib here (self-test)")' >"$scratch/no-matplotlib/matplotlib/__init__.py"
echo '{"camera": {}, "frames": [{"step": 0}]}' >"$scratch/frames.json"
expect_exit_2 "render-figures --animate without matplotlib" "needs matplotlib" \
  env PYTHONPATH="$scratch/no-matplotlib" python3 "$root/scripts/render-figures.py" --animate "$scratch/frames.json" \
  "$scratch/out.gif"
expect_exit_2 "render-figures --animate, no such file" "missing.json" \
  python3 "$root/scripts/render-figures.py" --animate "$scratch/missing.json" "$scratch/out.gif"
echo '{"frames": []}' >"$scratch/not-frames.json"
expect_exit_2 "render-figures --animate, frames without a camera" "not frames of a scene with a camera" \
  python3 "$root/scripts/render-figures.py" --animate "$scratch/not-frames.json" "$scratch/out.gif"
echo '{"kind": "world_frames", "camera": {}, "frames": [{"step": 0}]}' >"$scratch/world-frames.json"
expect_exit_2 "render-figures --animate, world frames without bodies" "world frames without bodies or methods" \
  python3 "$root/scripts/render-figures.py" --animate "$scratch/world-frames.json" "$scratch/out.gif"
expect_exit_2 "render-figures --animate, a GIF in no directory" "does not exist" \
  python3 "$root/scripts/render-figures.py" --animate "$scratch/frames.json" "$scratch/nowhere/out.gif"
expect_exit_2 "render-figures, an unknown argument" "unknown arguments --chekc" \
  python3 "$root/scripts/render-figures.py" --chekc

# ---- error-concentration.py ---------------------------------------------------------------------------------------
frames() {  # frames PLAIN_POINTS SUBJECT_POINTS: a frames document with one frame
  printf '{"kind": "frames", "net": {"name": "n", "extent": 2.0}, "compression": 0.3, "calibrated": false,
           "frames": [{"step": 1, "plain": %s, "tcsb_surface": %s}]}\n' "$1" "$2" >"$scratch/points.json"
}
concentration() { python3 "$root/scripts/error-concentration.py" "$@"; }
frames '[[0, 0, 0], [1, 0, 0]]' '[[0, 0, 0], [1, 0]]'
expect_exit_2 "error-concentration, a point of two coordinates" "frames.0.tcsb_surface.1" concentration "$scratch/points.json"
frames '[[0, 0, 0], 7]' '[[0, 0, 0], [1, 0, 0]]'
expect_exit_2 "error-concentration, a point that is a number" "frames.0.plain.1" concentration "$scratch/points.json"
frames '[[0, 0, "a"]]' '[[0, 0, 0]]'
expect_exit_2 "error-concentration, a coordinate that is a string" "frames.0.plain.0" concentration "$scratch/points.json"
frames '5' '[[0, 0, 0]]'
expect_exit_2 "error-concentration, points that are not a list" "frames.0.plain" concentration "$scratch/points.json"
frames '[[0, 0, 0]]' '[[0, 0, 0], [1, 1, 1]]'
expect_exit_2 "error-concentration, lists of different lengths" "does not match" concentration "$scratch/points.json"
frames '[[0, 0, 0]]' '[[0, 0, 0]]'
expect_exit_2 "error-concentration, --worst not a number" "--worst" concentration "$scratch/points.json" --worst abc
expect_exit_2 "error-concentration, an unknown flag" "--wrost" concentration "$scratch/points.json" --wrost 5
expect_exit_2 "error-concentration, no such file" "missing.json" concentration "$scratch/missing.json"
# (and a good one passes, so the cases above fail for their own reason)
if ! concentration "$scratch/points.json" >/dev/null 2>&1; then
  echo "scripts-bad-input-self-test: FAIL: error-concentration refused a good frames file" >&2
  failures=$((failures + 1))
fi

# ---- gate-error-rates.sh ------------------------------------------------------------------------------------------
mkdir -p "$scratch/fakebin"
printf '#!/bin/sh\necho "fake cmake: the script went on to build" >&2\nexit 97\n' >"$scratch/fakebin/cmake"
chmod +x "$scratch/fakebin/cmake"
rates() { env PATH="$scratch/fakebin:$PATH" TCSB_BUILD_DIR="$scratch/build" bash "$root/scripts/gate-error-rates.sh" "$@"; }
expect_exit_2 "gate-error-rates 0" "got '0'" rates 0
expect_exit_2 "gate-error-rates 2.5" "got '2.5'" rates 2.5
expect_exit_2 "gate-error-rates -2" "got '-2'" rates -2
expect_exit_2 "gate-error-rates 3 4" "got '4'" rates 3 4
expect_exit_2 "gate-error-rates with three arguments" "at most two arguments" rates 3 2 1
expect_exit_2 "gate-error-rates, a slowdown that is no percentage" "TCSB_RATES_PERCENTS" \
  env TCSB_RATES_PERCENTS="5 x" PATH="$scratch/fakebin:$PATH" bash "$root/scripts/gate-error-rates.sh"
expect_exit_2 "gate-error-rates, a negative threshold" "TCSB_RATES_THRESHOLDS" \
  env TCSB_RATES_THRESHOLDS="-0.1" PATH="$scratch/fakebin:$PATH" bash "$root/scripts/gate-error-rates.sh"
if [ -e "$scratch/build" ]; then
  echo "scripts-bad-input-self-test: FAIL: gate-error-rates made a build tree before refusing its arguments" >&2
  failures=$((failures + 1))
fi

if ((failures > 0)); then
  echo "scripts-bad-input-self-test: $failures failure(s)" >&2
  exit 1
fi
echo "scripts-bad-input-self-test: all ok"
