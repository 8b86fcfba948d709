#!/usr/bin/env bash
# The library as a user gets it: installs the build tree BUILD into a scratch prefix, configures and builds
# examples/ against it with find_package(tcsb) in a tree of its own, and runs hello_tcsb and drape_tcsb (which check
# the cut's invariants, drape_tcsb also that the cloth rests on its sphere, and exit non-zero when that fails).
# Usage: scripts/check-example.sh BUILD
set -euo pipefail
build=${1:?usage: check-example.sh BUILD}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build" --prefix "$scratch/prefix" > "$scratch/install.log"
# Nothing of the source or build tree may be needed: the example sees only the prefix.
cmake -S "$source_dir/examples" -B "$scratch/examples" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$scratch/prefix" > "$scratch/configure.log"
cmake --build "$scratch/examples" > "$scratch/build.log"
"$scratch/examples/hello_tcsb" | tee "$scratch/run.log"
grep -q "invariants hold" "$scratch/run.log"
"$scratch/examples/drape_tcsb" | tee "$scratch/drape.log"
grep -q "(on the sphere); invariants hold" "$scratch/drape.log"
