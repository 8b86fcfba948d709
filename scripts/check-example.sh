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
# The package puts <prefix>/include alone on a user's include path, and its headers reach each other relative to
# themselves: a user's own headers of the generic names tcsb's modules use must never be picked up in their place.
# A user's header of the name of every header of the library modules (src/modules.txt) stops the build if any tcsb
# header includes it through the include path.
for module in $(awk '$2 == "library" {print $1}' "$source_dir/src/modules.txt"); do
  mkdir -p "$scratch/user-include/$module"
  for source in "$source_dir/src/$module"/*.h; do
    header=$module/$(basename "$source")
    echo "#error \"a tcsb header reached the user's own $header through the include path\"" \
      > "$scratch/user-include/$header"
  done
done
grep -q "include/tcsb\b[^/]" "$scratch/prefix"/lib*/cmake/tcsb/tcsbTargets.cmake &&
  { echo "check-example: the package puts include/tcsb itself on the include path" >&2; exit 1; }
# Nothing of the source or build tree may be needed: the example sees only the prefix (and the user's headers).
cmake -S "$source_dir/examples" -B "$scratch/examples" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$scratch/prefix" -DCMAKE_CXX_FLAGS="-I$scratch/user-include" > "$scratch/configure.log"
cmake --build "$scratch/examples" > "$scratch/build.log" || { cat "$scratch/build.log" >&2; exit 1; }
"$scratch/examples/hello_tcsb" | tee "$scratch/run.log"
grep -q "invariants hold" "$scratch/run.log"
"$scratch/examples/drape_tcsb" | tee "$scratch/drape.log"
grep -q "(on the sphere); invariants hold" "$scratch/drape.log"
