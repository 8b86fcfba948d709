#!/usr/bin/env bash
# Second command of the README (and what CI runs): install what is missing, build, run every test, gate the
# performance against the committed baseline, then build again with AddressSanitizer + UndefinedBehaviorSanitizer
# and run every test once more. Any failure stops it with a non-zero exit.
set -euo pipefail
cd "$(dirname "$0")/.."
# Google Benchmark's compare.py (libbenchmark-tools, which needs SciPy) for the test that it reads our exports;
# clang-format for the format check; Slurm and munge for the test on a real single-node cluster
# (scripts/test-slurm.sh).
bash scripts/install-deps.sh libbenchmark-tools python3-scipy clang-format slurm-wlm munge
# Formatting first, so a format problem fails in seconds: every C++ source as .clang-format says.
bash scripts/check-format.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build  # every target: the tests and benchmarks too (setup-and-reproduce.sh builds tcsb alone)
ctest --test-dir build --output-on-failure -j2

# Regression gate: a fresh run of the ci suite against results/baselines/ci.json. N, L, I, operations and final
# states must match exactly; TC-SB/plain step-time ratios (same run) must not regress; absolute step times only
# warn, since CI machines differ. A change that alters behaviour refreshes the baseline in the same commit
# (scripts/refresh-baseline.sh).
gate_dir=$(mktemp -d)
trap 'rm -rf "$gate_dir"' EXIT
build/tcsb run ci --quiet --out "$gate_dir/ci.json"
# CI gates ratio changes above 25 % (the command's default is 5 %, for a dedicated machine): the baseline and this
# run happen at different times on a shared 2-core VM, and unchanged reruns there have drifted by up to 15 % on
# single cases with every repetition shifted (measured 2026-11-22: n41/tcsb@0.75 0.763 -> 0.878). A real
# slowdown of the TC-SB step (the injected 200 us delay of scripts/gate-self-test.sh) is far above that.
# Behaviour (N, L, I, operations, final-state hashes) is still gated exactly.
# A timing-only failure is measured once more before it counts: a real slowdown persists, a background hiccup
# rarely repeats. A behaviour change fails at once.
if ! build/tcsb compare --threshold 0.25 --summary "$gate_dir/summary.md" results/baselines/ci.json "$gate_dir/ci.json"; then
  cat "$gate_dir/summary.md" >&2
  grep -q ", 0 behaviour changes" "$gate_dir/summary.md" || exit 1
  echo "test.sh: timing regression flagged; measuring the ci suite once more" >&2
  build/tcsb run ci --quiet --out "$gate_dir/ci-rerun.json"
  build/tcsb compare --threshold 0.25 results/baselines/ci.json "$gate_dir/ci-rerun.json"
fi

# Sanitizers: a separate tree, every test, any report fatal; the CLI tests run the sanitized tcsb binary too. Debug
# (-O0 -g, asserts on) compiles in about a third of the CPU time RelWithDebInfo needs with sanitizers, and the
# tests stay fast enough. allocator_may_return_null=1: a failed allocation returns null as glibc's malloc does (ASan
# would abort instead), so the tests of what tcsb then does (softbody/bullet_allocator.h: throw, exit 2) test tcsb.
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Debug -DTCSB_SANITIZE=ON -DTCSB_BUILD_BENCH=OFF
cmake --build build-sanitize
ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:allocator_may_return_null=1 \
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure -j2
