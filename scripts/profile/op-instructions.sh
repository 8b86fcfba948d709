#!/usr/bin/env bash
# Instructions and simulated cache misses (not seconds) per TreeCut operation at two net sizes, counted by callgrind
# on the micro-benchmark: shows whether an operation's work depends on the size of the net, and how many cache
# lines it fetches from beyond a 2 MiB last-level cache (the L2 of the development VM; callgrind simulates two
# levels, 48 KiB L1 and that), independently of machine noise: the counts are deterministic.
# Only the benchmark loops are counted, not the fixture's setup, and of each benchmark only the timed operations.
# Usage: bash scripts/profile/op-instructions.sh [build-dir] [widths...]   (needs valgrind; takes a few minutes)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
shift || true
widths=${*:-33 257}
command -v valgrind >/dev/null || { echo "op-instructions: valgrind is not installed" >&2; exit 2; }
for width in $widths; do
  dir=$(mktemp -d)
  # bench/op_bench.cpp zeroes the counters when a benchmark loop starts and dumps them when it ends. One repetition,
  # not interleaved, so the dumps cg.out.1..4 come in registration order: BM_Refine, BM_EndRefine, BM_Coarse,
  # BM_EndCoarse. Each dump also holds the untimed operations that undo the timed ones (a refine's undo is a coarse
  # of the block it just refined, its lines still warm), so only the timed kind is read from each.
  TCSB_BENCH_OP_ITERS=2000 valgrind --tool=callgrind --cache-sim=yes --D1=49152,12,64 --LL=2097152,16,64 \
    --callgrind-out-file="$dir/cg.out" \
    "$build/tcsb_bench" --benchmark_filter="BM_(Refine|EndRefine|Coarse|EndCoarse)/width:$width/" \
    --benchmark_repetitions=1 --benchmark_enable_random_interleaving=false >/dev/null 2>&1
  echo "width $width:"
  i=1
  for op in begin_refine end_refine begin_coarse end_coarse; do
    python3 scripts/profile/callgrind_calls.py --only "$op" "$dir/cg.out.$i"
    i=$((i + 1))
  done
  rm -rf "$dir"
done
