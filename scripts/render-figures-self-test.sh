#!/usr/bin/env bash
# Tests scripts/render-figures.py --check on a scratch copy of the script, the kept runs and the figures: it passes
# on the copy as committed, and fails (exit 1) when a newer kept run holds Figure 4's data, when a kept input
# changes, when a PNG is replaced by hand and when the script changes; with no input for a figure it exits 2.
# Needs no matplotlib. Usage: bash scripts/render-figures-self-test.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

fresh_copy() {
  rm -rf "$scratch/tree"
  mkdir -p "$scratch/tree/scripts" "$scratch/tree/results"
  cp "$root/scripts/render-figures.py" "$scratch/tree/scripts/"
  cp -r "$root/results/runs" "$root/results/figures" "$scratch/tree/results/"
}
check() {  # the exit code of --check on the copy
  local status=0
  TCSB_FIGURES_ROOT=$scratch/tree python3 "$scratch/tree/scripts/render-figures.py" --check 2>"$scratch/err" || status=$?
  echo "$status"
}
expect() {  # expect WHAT STATUS
  local got
  got=$(check)
  if [[ $got != "$2" ]]; then
    echo "render-figures-self-test: FAIL: $1: exit $got, expected $2" >&2
    cat "$scratch/err" >&2
    exit 1
  fi
  echo "render-figures-self-test: ok    $1: exit $got"
}

fresh_copy
expect "the committed figures" 0

fresh_copy
newest=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["figures"]["fig4_operations.png"]["from"])' \
  "$scratch/tree/results/figures/manifest.json")
cp "$scratch/tree/$newest" "$scratch/tree/results/runs/9999-12-31-0000000-paper.json"
expect "a newer kept paper run" 1

fresh_copy
frames=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["figures"]["fig6_frames.png"]["from"])' \
  "$scratch/tree/results/figures/manifest.json")
printf ' ' >>"$scratch/tree/$frames"
expect "a kept input changed" 1

fresh_copy
printf 'x' >>"$scratch/tree/results/figures/fig5_step_time.png"
expect "a PNG replaced by hand" 1

fresh_copy
printf '\n' >>"$scratch/tree/scripts/render-figures.py"
expect "the script changed" 1

fresh_copy
rm -rf "$scratch/tree/results/runs/frames"
expect "no input for Figure 6" 2
