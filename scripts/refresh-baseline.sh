#!/usr/bin/env bash
# Refreshes the CI gates' baselines: builds Release, runs the ci suite into results/baselines/ci.json (the wall-time
# gate) and the ci-instructions suite under callgrind into results/baselines/ci-instructions.json (the instruction
# gate; needs valgrind, about a minute).
#
# The gate (`tcsb compare`, run by scripts/test.sh) requires N, L, I, operations and every final-state hash to
# match the baseline exactly, and refuses a baseline of another suite. So run this, and commit its output, in the
# same commit as any change that changes behaviour or edits suites/ci.json. Timings are gated as same-run ratios,
# which any machine can produce; a quiet machine gives the least noisy baseline. Instruction counts depend on the
# code, the compiler and Bullet, not on the machine's load: refresh them with any change meant to change a step's
# work (the instruction gate fails a case that counts more than 0.5 % more).
# Usage: bash scripts/refresh-baseline.sh            (TCSB_BUILD_DIR overrides the build directory, default build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TCSB_BUILD_DIR:-build}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target tcsb
mkdir -p results/baselines
"$build/tcsb" run ci --quiet --out results/baselines/ci.json
"$build/tcsb" run ci-instructions --measure instructions --quiet --out results/baselines/ci-instructions.json
echo "refresh-baseline: wrote results/baselines/ci.json and ci-instructions.json ($("$build/tcsb" --version))" >&2
