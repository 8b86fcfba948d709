#!/usr/bin/env bash
# First command of the README: install what is missing, build (Release) the tcsb executable alone (and the libraries
# it links; not the tests or benchmarks, which scripts/test.sh builds), run the default reproduction.
# Installing and building talk on stderr, so stdout carries only the report: `... > reproduction.json` is JSON.
set -euo pipefail
cd "$(dirname "$0")/.."
{
  bash scripts/install-deps.sh
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
  cmake --build build --target tcsb
} >&2
build/tcsb "$@"
