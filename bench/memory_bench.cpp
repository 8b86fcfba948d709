// Memory benchmarks: what one cache miss costs on this machine, and how many can overlap. No TC-SB code runs here.
//
// Why they are in this bench: beyond the L2 an operation's time is set by its cache misses, not by its work
// (docs/methodology.md, "Operations in constant time"). How flat an operation's cost can be in N is therefore
// bounded by the machine: at least (dependent levels of misses) x (latency of one miss), and at least
// (lines touched) / (misses in flight) rounds of that latency. This benchmark measures the two machine figures, so
// the bound can be recomputed on any machine (docs/methodology.md, "The memory floor").
//
// BM_DependentLoads/MiB:m/chains:k walks k independent pointer chains through one buffer of m MiB whose 64-byte lines
// are linked in a single random cycle (Sattolo's algorithm: every line once, no short loops), k steps per round —
// each step of a chain needs the line the previous step loaded, the k chains are independent of each other. The
// counter `per_round` is the wall time of one round: with k = 1 the latency of one miss; as k grows it stays
// flat while the core overlaps the misses and then grows with k once it runs out of slots. The buffer is 4 KiB-paged
// like the bodies' arrays (glibc does not ask for huge pages by default), so TLB misses count as they do there.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <vector>

namespace tcsb::bench {
namespace {

struct alignas(64) Line {
  const Line* next;
};
static_assert(sizeof(Line) == 64);

/// One buffer per size, its lines linked in a random cycle; `order` lists the cycle, so k chains can start evenly
/// spaced along it and never meet.
struct ChainBuffer {
  std::vector<Line> lines;
  std::vector<std::uint32_t> order;
};

const ChainBuffer& chain_buffer(std::size_t mib) {
  static std::map<std::size_t, std::unique_ptr<ChainBuffer>> cache;
  auto& slot = cache[mib];
  if (!slot) {
    slot = std::make_unique<ChainBuffer>();
    const std::size_t n = mib * 1024 * 1024 / sizeof(Line);
    slot->order.resize(n);
    for (std::size_t i = 0; i < n; ++i) slot->order[i] = static_cast<std::uint32_t>(i);
    std::mt19937_64 rng(20261122);
    for (std::size_t i = n - 1; i > 0; --i) {  // Sattolo: a single cycle through all n lines
      std::uniform_int_distribution<std::size_t> pick(0, i - 1);
      std::swap(slot->order[i], slot->order[pick(rng)]);
    }
    slot->lines.resize(n);
    for (std::size_t i = 0; i < n; ++i) slot->lines[slot->order[i]].next = &slot->lines[slot->order[(i + 1) % n]];
  }
  return *slot;
}

void BM_DependentLoads(benchmark::State& state) {
  const auto mib = static_cast<std::size_t>(state.range(0));
  const auto chains = static_cast<std::size_t>(state.range(1));
  const ChainBuffer& buffer = chain_buffer(mib);
  const std::size_t n = buffer.lines.size();
  std::vector<const Line*> at(chains);
  for (std::size_t j = 0; j < chains; ++j) at[j] = &buffer.lines[buffer.order[j * n / chains]];
  // Each chain walks 1/k of the cycle per 'rounds' rounds at most; far fewer here, so the lines stay cold.
  constexpr std::int64_t kRounds = 4096;
  for (auto _ : state) {
    for (std::int64_t r = 0; r < kRounds; ++r)
      for (std::size_t j = 0; j < chains; ++j) at[j] = at[j]->next;
    benchmark::DoNotOptimize(at.data());
    benchmark::ClobberMemory();
  }
  // Seconds per round (printed with an SI prefix: "184n" is 184 ns).
  state.counters["per_round"] = benchmark::Counter(static_cast<double>(state.iterations() * kRounds),
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// 1 MiB fits this VM's 2 MiB L2 (the reference); 128 MiB is the scale of the largest bench body (513^2).
BENCHMARK(BM_DependentLoads)
    ->ArgNames({"MiB", "chains"})
    ->Args({1, 1})
    ->Args({128, 1})
    ->Args({128, 2})
    ->Args({128, 4})
    ->Args({128, 8})
    ->Args({128, 12})
    ->Args({128, 16})
    ->Args({128, 24})
    ->Args({128, 32})
    ->MinTime(0.05);

}  // namespace
}  // namespace tcsb::bench
