// Step benchmarks: one Bullet step of the plain baseline and of a TC-SB body at its finest cut with no operations
// (so the same nodes and links; the difference is TC-SB's per-step overhead). piterations 2, gravity, timed from a
// swinging state: each run builds a fresh body and lets it fall for kWarmupSteps first, untimed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "bench_bodies.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"

namespace tcsb::bench {
namespace {

constexpr int kWarmupSteps = 30;

bool finite(const btSoftBody& body) {
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    const btVector3& x = body.m_nodes[i].m_x;
    if (!std::isfinite(x.x()) || !std::isfinite(x.y()) || !std::isfinite(x.z())) return false;
  }
  return true;
}

void set_counters(benchmark::State& state, const btSoftBody& body) {
  state.SetComplexityN(body.m_nodes.size());
  state.counters["N"] = body.m_nodes.size();
  state.counters["L"] = body.m_links.size();
  if (!finite(body)) state.SkipWithError("the body diverged (non-finite positions)");
}

void BM_PlainStep(benchmark::State& state) {
  SceneWorld world{WorldSettings{}};
  const auto net = square_net(static_cast<int>(state.range(0)));
  const auto body = make_plain_softbody(world.info(), *net, bench_solver());
  for (int s = 0; s < kWarmupSteps; ++s) step_soft_body(*body, kDt);
  for (auto _ : state) step_soft_body(*body, kDt);
  set_counters(state, *body);
}

void BM_TcsbStepNoOps(benchmark::State& state) {
  SceneWorld world{WorldSettings{}};
  const auto net = square_net(static_cast<int>(state.range(0)));
  TcSoftBody body(world.info(), net, bench_solver(), TcSettings{});
  for (int s = 0; s < kWarmupSteps; ++s) {
    body.advance_blends();
    body.simulate_step(kDt);
  }
  // As the runner steps a TC-SB body: blends advance at the step boundary (nothing in flight here), then Bullet.
  for (auto _ : state) {
    body.advance_blends();
    body.simulate_step(kDt);
  }
  if (body.interpolations() != 0 || body.committed_count() != static_cast<int>(net->node_count()))
    state.SkipWithError("TC-SB body left its finest cut");
  set_counters(state, body);
}

// The same plain body with its links in the net's order (CreatePatch's: each node's +x link, then its +z link) and in
// the order Bullet's own btSoftBody::randomizeConstraints() shuffles them into, at 2 and 32 position iterations. The
// link solve is a Gauss-Seidel sweep: in the net's order consecutive links share a node, so each waits for the last
// one's write to it; shuffled, the processor overlaps them. Same instructions, not the same time
// (docs/investigations/link-order.md).
void BM_PlainStepLinkOrder(benchmark::State& state) {
  SceneWorld world{WorldSettings{}};
  const auto net = square_net(static_cast<int>(state.range(0)));
  SolverSettings solver = bench_solver();
  solver.piterations = static_cast<int>(state.range(2));
  const auto body = make_plain_softbody(world.info(), *net, solver);
  if (state.range(1) != 0) body->randomizeConstraints();
  for (int s = 0; s < kWarmupSteps; ++s) step_soft_body(*body, kDt);
  for (auto _ : state) step_soft_body(*body, kDt);
  set_counters(state, *body);
}

void step_args(benchmark::internal::Benchmark* b) {
  for (int w : kStepWidths) b->Arg(w);
  b->ArgName("width")->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
}

BENCHMARK(BM_PlainStep)->Apply(step_args);
BENCHMARK(BM_TcsbStepNoOps)->Apply(step_args);
BENCHMARK(BM_PlainStepLinkOrder)
    ->ArgsProduct({{33, 65, 129}, {0, 1}, {2, 32}})
    ->ArgNames({"width", "shuffled", "piterations"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace tcsb::bench
