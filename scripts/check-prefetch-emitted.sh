#!/usr/bin/env bash
# Checks that the compiler kept the software prefetches of src/softbody/tc_prefetch.cpp. GCC treats
# __builtin_prefetch as free of effects and may delete a loop that does nothing else, silently: the code then still
# builds and passes every test, and only the benchmarks get slower (this happened twice while experimenting;
# docs/methodology.md, "Tried and left out"). So CTest counts the prefetch instructions in each function's
# disassembly and requires at least one per prefetch call in the source, which a deleted wave or loop falls below.
# Usage: check-prefetch-emitted.sh OBJDUMP OBJECTS   (the library's objects, as arguments or one ;-separated list;
# tc_prefetch.cpp's is picked out)
set -euo pipefail
objdump=$1
shift
object=""
for arg in "$@"; do
  IFS=';' read -r -a objects <<<"$arg"  # CTest hands over $<TARGET_OBJECTS:...> as one ;-separated argument
  for o in "${objects[@]}"; do
    case $o in *tc_prefetch.cpp.o | *tc_prefetch.cpp.obj) object=$o ;; esac
  done
done
[ -n "$object" ] || { echo "check-prefetch-emitted: no tc_prefetch.cpp object among the arguments" >&2; exit 2; }

# Prefetch calls in the source, counting the helpers' expansions: prefetch() 1, prefetch_object() 2,
# prefetch_node() 3.
#   prefetch_footprint:     waves 1-4 = 5 + 5 + 3 + 2
#   prefetch_link_removals: 3 + 2
declare -A minimum=([prefetch_footprint]=15 [prefetch_link_removals]=5)

counts=$("$objdump" -d --no-show-raw-insn -C "$object" | awk '
  /^[0-9a-f]+ <.*>:$/ { fn = $0; next }
  $2 ~ /^prefetch/ && fn ~ /TcSoftBody::Impl::prefetch_footprint\(/ { n["prefetch_footprint"]++ }
  $2 ~ /^prefetch/ && fn ~ /TcSoftBody::Impl::prefetch_link_removals\(/ { n["prefetch_link_removals"]++ }
  END { for (f in n) print f, n[f] }')

status=0
for fn in "${!minimum[@]}"; do
  found=$(awk -v f="$fn" '$1 == f { print $2 }' <<<"$counts")
  found=${found:-0}
  if [ "$found" -lt "${minimum[$fn]}" ]; then
    echo "check-prefetch-emitted: TcSoftBody::Impl::$fn has $found prefetch instructions, expected at least ${minimum[$fn]}: the compiler dropped some (use asm volatile prefetches where a loop only prefetches)" >&2
    status=1
  else
    echo "TcSoftBody::Impl::$fn: $found prefetch instructions (at least ${minimum[$fn]})"
  fi
done
exit $status
