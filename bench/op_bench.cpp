// Per-operation benchmarks: the cost of ONE TreeCut operation (refine, end-refine, coarse, end-coarse) on a body of
// 33^2 .. 513^2 grid nodes at a mixed, swinging cut. Each iteration times exactly one call with steady_clock
// (UseManualTime); everything around it — finding a block, the other K-1 blend steps, undoing the operation so the
// cut stays as it was — runs untimed.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/statistics.h"
#include "bench_bodies.h"
#include "softbody/op_sample.h"
#include "softbody/tc_softbody_impl.h"

// scripts/profile/op-instructions.sh runs this benchmark under callgrind: the loop below zeroes the counters when it
// starts and dumps them when it ends, so each dump covers the measured operations and not the fixture's setup (which
// drives the cut to half the net with thousands of operations at random places). Without valgrind these do nothing.
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define TCSB_CALLGRIND_ZERO_STATS() CALLGRIND_ZERO_STATS
#define TCSB_CALLGRIND_DUMP_STATS() CALLGRIND_DUMP_STATS
#else
#define TCSB_CALLGRIND_ZERO_STATS() ((void)0)
#define TCSB_CALLGRIND_DUMP_STATS() ((void)0)
#endif

namespace tcsb::bench {
namespace {

// Same order as OpKind, so a Timed indexes per-kind arrays.
enum class Timed {
  kRefine = static_cast<int>(OpKind::kRefine),
  kEndRefine = static_cast<int>(OpKind::kEndRefine),
  kCoarse = static_cast<int>(OpKind::kCoarse),
  kEndCoarse = static_cast<int>(OpKind::kEndCoarse)
};

/// Runs `blend_steps` advance_blends() calls and returns the time of the last one, which ends the (only) operation
/// in flight.
double finish_blend(TcSoftBody& body, bool time_last) {
  const int k = body.settings().blend_steps;
  for (int s = 0; s + 1 < k; ++s) body.advance_blends();
  if (time_last) return time_call([&] { body.advance_blends(); });
  body.advance_blends();
  return 0.0;
}

/// Coarse of p, then refine back (or the reverse): one round trip, timing the named part.
double coarse_round_trip(TcSoftBody& body, TreeId p, Timed timed, long long& restore_failures) {
  double t = 0.0;
  if (timed == Timed::kCoarse)
    t = time_call([&] { body.begin_coarse(p); });
  else
    body.begin_coarse(p);
  const double end = finish_blend(body, timed == Timed::kEndCoarse);
  if (timed == Timed::kEndCoarse) t = end;
  // Undo, untimed: the block's neighbours were fine enough for its children before, so refining it is allowed.
  if (body.can_refine(p).ok) {
    body.begin_refine(p);
    finish_blend(body, false);
  } else {
    ++restore_failures;
  }
  return t;
}

double refine_round_trip(TcSoftBody& body, TreeId q, Timed timed, long long& restore_failures) {
  double t = 0.0;
  if (timed == Timed::kRefine)
    t = time_call([&] { body.begin_refine(q); });
  else
    body.begin_refine(q);
  const double end = finish_blend(body, timed == Timed::kEndRefine);
  if (timed == Timed::kEndRefine) t = end;
  if (body.can_coarsen(q).ok) {
    body.begin_coarse(q);
    finish_blend(body, false);
  } else {
    ++restore_failures;
  }
  return t;
}

void run_op(benchmark::State& state, Timed timed, const char* name) {
  OpBody& fixture = op_body(static_cast<int>(state.range(0)));
  TcSoftBody& body = *fixture.body;
  if (body.interpolations() != 0) {
    state.SkipWithError("body has operations in flight before the benchmark");
    return;
  }
  const long long nodes = body.node_count(), links = body.link_count();
  const int committed_before = body.committed_count();
  const bool coarse_first = timed == Timed::kCoarse || timed == Timed::kEndCoarse;
  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(state.max_iterations));
  long long restore_failures = 0;
  std::vector<double> node_part, link_part;
  node_part.reserve(samples.capacity());
  link_part.reserve(samples.capacity());
  // Per kind, the latest sample the body reported (indexed like Timed, which follows OpKind's order).
  struct KindSink : OpSink {
    explicit KindSink(OpSample* out) : out(out) {}
    void record(const OpSample& sample) override { out[static_cast<int>(sample.kind)] = sample; }
    OpSample* out;
  };
  OpSample timed_sample[kOpKindCount];
  KindSink sink(timed_sample);
  body.impl().set_op_sink(&sink);

  // One round trip on a random block; the timed part's seconds, or nullopt when no block qualifies.
  const auto random_round_trip = [&]() -> std::optional<double> {
    const TreeId id = coarse_first ? fixture.coarse_candidate() : fixture.refine_candidate();
    if (id == kNoTreeNode) return std::nullopt;
    return coarse_first ? coarse_round_trip(body, id, timed, restore_failures)
                        : refine_round_trip(body, id, timed, restore_failures);
  };

  // Untimed round trips first, so every repetition starts from the steady state a stream of operations keeps the
  // caches in. Without them, the repetitions interleaved with other sizes (main()) would time a small body's first
  // few thousand calls against lines the previous benchmark evicted, and a size would be measured by what ran before
  // it. 1 000 random round trips touch a 65^2 body's per-node data several times over.
  for (int i = 0; i < kWarmupRoundTrips; ++i)
    if (!random_round_trip()) break;

  TCSB_CALLGRIND_ZERO_STATS();
  for (auto _ : state) {
    const std::optional<double> measured = random_round_trip();
    if (!measured) {
      state.SkipWithError("no block found for the operation");
      break;
    }
    const double seconds = *measured;
    state.SetIterationTime(seconds);
    samples.push_back(seconds * 1e9);
    // The round trip emits two begin and two end samples; keep the one of the timed kind.
    node_part.push_back(timed_sample[static_cast<int>(timed)].node_ns);
    link_part.push_back(timed_sample[static_cast<int>(timed)].link_ns);
  }

  TCSB_CALLGRIND_DUMP_STATS();
  body.impl().set_op_sink(nullptr);
  if (body.interpolations() != 0) state.SkipWithError("an operation was left in flight");
  state.SetComplexityN(nodes);
  state.counters["N"] = static_cast<double>(nodes);
  state.counters["L"] = static_cast<double>(links);
  state.counters["med_ns"] = median(samples);
  state.counters["p90_ns"] = percentile(samples, 90);
  state.counters["p99_ns"] = percentile(samples, 99);
  state.counters["node_ns"] = median(node_part);
  state.counters["link_ns"] = median(link_part);
  // Cut size change over the run, ~0; like restore_fail, set only when non-zero, because Google Benchmark's
  // coefficient of variation over repetitions of an all-zero counter is 0/0, which it writes into JSON as NaN.
  if (const int drift = body.committed_count() - committed_before) state.counters["drift"] = drift;
  if (restore_failures) state.counters["restore_fail"] = static_cast<double>(restore_failures);

  OpRun run;
  run.op = name;
  run.width = fixture.width;
  run.nodes = nodes;
  run.ns = std::move(samples);
  run.node_ns = std::move(node_part);
  run.link_ns = std::move(link_part);
  op_runs().push_back(std::move(run));
}

void BM_Refine(benchmark::State& state) { run_op(state, Timed::kRefine, "BM_Refine"); }
void BM_EndRefine(benchmark::State& state) { run_op(state, Timed::kEndRefine, "BM_EndRefine"); }
void BM_Coarse(benchmark::State& state) { run_op(state, Timed::kCoarse, "BM_Coarse"); }
void BM_EndCoarse(benchmark::State& state) { run_op(state, Timed::kEndCoarse, "BM_EndCoarse"); }

/// Widths as arguments; a fixed iteration count so each size takes about the same short wall time (the untimed
/// round trip around each measured call costs ~10x the call itself, so min-time in manual-time units would run far
/// longer than it says).
void op_args(benchmark::internal::Benchmark* b) {
  for (int w : kOpWidths) b->Arg(w);
  b->ArgName("width")->UseManualTime()->Iterations(op_iterations())->Complexity(benchmark::o1);
}

BENCHMARK(BM_Refine)->Apply(op_args);
BENCHMARK(BM_EndRefine)->Apply(op_args);
BENCHMARK(BM_Coarse)->Apply(op_args);
BENCHMARK(BM_EndCoarse)->Apply(op_args);

}  // namespace
}  // namespace tcsb::bench
