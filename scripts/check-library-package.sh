#!/usr/bin/env bash
# The library as a game adopts it (docs/library.md): configures the source tree library-only (TCSB_BUILD_HARNESS=OFF,
# which must find nothing of the harness's dependencies), builds and installs it into a scratch prefix, checks that
# the package holds the library alone and refuses a client asking for another minor version, compiles each public
# header (include/tcsb/*.h) alone as the first include of a file of its own, then builds the examples against it as a C++17 project (the package's targets must raise it to C++20) and runs the client's
# scenario (client_tcsb: a cloth on a sphere anchored to a moving body, two bodies in one world, one removed and
# destroyed mid-run, budget and camera changed mid-run), which exits non-zero when an invariant, the anchor or the
# budget fails.
# Usage: scripts/check-library-package.sh [--sanitize]
#   --sanitize: the library and the client built with AddressSanitizer and UndefinedBehaviorSanitizer (Debug), only
#               client_tcsb built and run, any report fatal.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
lib_flags=(-DCMAKE_BUILD_TYPE=Release)
client_flags=(-DCMAKE_BUILD_TYPE=Release)
targets=()
if [ "${1:-}" = "--sanitize" ]; then
  lib_flags=(-DCMAKE_BUILD_TYPE=Debug -DTCSB_SANITIZE=ON -DCMAKE_UNITY_BUILD=ON)
  sanitize="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
  client_flags=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS=$sanitize" "-DCMAKE_EXE_LINKER_FLAGS=$sanitize")
  targets=(--target client_tcsb)
fi
command -v ccache > /dev/null && lib_flags+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

cmake -S "$source_dir" -B "$scratch/lib" -G Ninja -DTCSB_BUILD_HARNESS=OFF "${lib_flags[@]}" > "$scratch/configure.log"
if grep -Eq "^(CLI11|nlohmann_json|GTest|benchmark)_DIR:" "$scratch/lib/CMakeCache.txt"; then
  echo "check-library-package: the library-only configure looked for a harness dependency" >&2
  exit 1
fi
cmake --build "$scratch/lib" > "$scratch/build.log" || { cat "$scratch/build.log" >&2; exit 1; }
cmake --install "$scratch/lib" --prefix "$scratch/prefix" > "$scratch/install.log"
[ ! -e "$scratch/prefix/bin" ] || { echo "check-library-package: the library-only install has executables" >&2; exit 1; }

# Each public header compiles alone, with nothing but the package's own include paths: a user may include any one
# of them first (docs/library.md). (What they may include is checked by scripts/check-include-walls.py.)
mkdir -p "$scratch/alone"
headers=$(cd "$scratch/prefix/include/tcsb" && ls ./*.h | sed 's|^\./||')
{
  printf 'cmake_minimum_required(VERSION 3.25)\nproject(alone LANGUAGES CXX)\nfind_package(tcsb REQUIRED)\n'
  for header in $headers; do
    printf '#include <tcsb/%s>\n' "$header" > "$scratch/alone/${header%.h}.cpp"
    printf 'add_library(alone_%s OBJECT %s.cpp)\ntarget_link_libraries(alone_%s PRIVATE tcsb::tcsb)\n' \
      "${header%.h}" "${header%.h}" "${header%.h}"
  done
} > "$scratch/alone/CMakeLists.txt"
cmake -S "$scratch/alone" -B "$scratch/alone/build" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
  "${client_flags[@]}" > "$scratch/alone-configure.log"
cmake --build "$scratch/alone/build" -- -k 0 > "$scratch/alone-build.log" 2>&1 ||
  { grep -E "error|FAILED" "$scratch/alone-build.log" >&2
    echo "check-library-package: a public header does not compile alone" >&2
    exit 1; }

# A client written for another minor version (0.1: tcsb::SoftBodyWorld, the one-body driver) must not find it.
mkdir -p "$scratch/old-client"
printf 'cmake_minimum_required(VERSION 3.25)\nproject(old LANGUAGES CXX)\nfind_package(tcsb 0.1 REQUIRED)\n' \
  > "$scratch/old-client/CMakeLists.txt"
if cmake -S "$scratch/old-client" -B "$scratch/old-client/build" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
     > "$scratch/old-client.log" 2>&1; then
  echo "check-library-package: find_package(tcsb 0.1) accepted the $(grep -o 'PACKAGE_VERSION "[^"]*"' \
    "$scratch/prefix"/lib*/cmake/tcsb/tcsbConfigVersion.cmake) package" >&2
  exit 1
fi
# ... refused for its version, not for another reason.
tr -s ' \n' ' ' < "$scratch/old-client.log" | grep -q 'compatible with requested version "0.1"' ||
  { cat "$scratch/old-client.log" >&2; exit 1; }

cmake -S "$source_dir/examples" -B "$scratch/examples" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
  -DCMAKE_CXX_STANDARD=17 "${client_flags[@]}" > "$scratch/examples-configure.log"
cmake --build "$scratch/examples" "${targets[@]}" > "$scratch/examples-build.log" ||
  { cat "$scratch/examples-build.log" >&2; exit 1; }
ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:abort_on_error=1:detect_leaks=1} \
UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1} \
  "$scratch/examples/client_tcsb" | tee "$scratch/client.log"
grep -q "invariants hold" "$scratch/client.log"
