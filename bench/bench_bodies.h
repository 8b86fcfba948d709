// Shared fixtures for the micro-benchmarks: square nets by width, TC-SB bodies brought to a mixed swinging cut
// (built once per width and cached), fresh plain and TC-SB bodies for the step benchmarks, and the log the
// per-operation benchmarks fill for the flatness summary main() prints.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "net/net.h"
#include "scene/scene_world.h"
#include "softbody/solver_settings.h"
#include "softbody/tc_settings.h"
#include "softbody/tc_softbody.h"

namespace tcsb::bench {

/// Net widths of the per-operation benchmarks: 1 089 to 263 169 grid nodes.
inline constexpr int kOpWidths[] = {33, 65, 129, 257, 513};
/// Net widths of the step benchmarks.
inline constexpr int kStepWidths[] = {33, 65, 129};
/// Measured operations per size, benchmark and repetition (each iteration also runs an untimed round trip ~10x its
/// cost). TCSB_BENCH_OP_ITERS in the environment overrides it, e.g. for quick runs while developing.
inline constexpr int kOpIterations = 2000;
int op_iterations();
/// Why TCSB_BENCH_OP_ITERS is unusable (set, but not a positive whole number), or nullopt; main() exits 2 on it.
std::optional<std::string> op_iterations_error();
/// Repetitions main() asks for unless the command line says otherwise, randomly interleaved across sizes and
/// benchmarks: flatness compares sizes, and on a shared VM whose speed drifts by tens of percent within minutes, sizes
/// measured one after the other would compare moments, not sizes. 5 x 2 000 = 10 000 measured calls per size.
inline constexpr int kDefaultRepetitions = 5;
/// Untimed round trips before each repetition's measured ones (op_bench.cpp).
inline constexpr int kWarmupRoundTrips = 1000;
/// Step size of every benchmark body, seconds.
inline constexpr btScalar kDt = btScalar(1.0 / 60.0);

/// The benchmark cloth: 8 m square at 8 m height, 1 kg in all, four corners pinned, structural links.
std::shared_ptr<const Net> square_net(int width);
/// piterations 2, everything else at the suite defaults.
SolverSettings bench_solver();

/// A TC-SB body of one width, brought to a mixed cut of about half its grid nodes while swinging under gravity, with
/// no operation in flight. Built once per width (op_body) and shared by the four operation benchmarks, which leave
/// its cut as they found it.
struct OpBody {
  explicit OpBody(int width);
  OpBody(const OpBody&) = delete;
  OpBody& operator=(const OpBody&) = delete;

  /// A parent p of a random cut node with can_coarsen(p).ok, or kNoTreeNode after `attempts` misses.
  TreeId coarse_candidate(int attempts = 100000);
  /// A random cut node q with can_refine(q).ok, or kNoTreeNode after `attempts` misses.
  TreeId refine_candidate(int attempts = 100000);

  int width;
  SceneWorld world;
  std::shared_ptr<const Net> net;
  std::unique_ptr<TcSoftBody> body;
  std::mt19937_64 rng;
  int setup_steps = 0;         ///< Bullet steps taken during setup
  double setup_seconds = 0.0;  ///< wall time of the setup, for the log
};

/// The cached body of a width (built on first use, outside any timed region).
OpBody& op_body(int width);

/// One finished run (one repetition) of a per-operation benchmark, for the flatness summary, which pools the
/// repetitions of each benchmark and size.
struct OpRun {
  std::string op;  ///< benchmark name, e.g. "BM_Refine"
  int width = 0;
  long long nodes = 0;                   ///< Bullet nodes when it ran (the N of the fit)
  std::vector<double> ns;                ///< each measured call
  std::vector<double> node_ns, link_ns;  ///< the body's own split of each call (OpSample)
};
/// Every per-operation run of this process, in order.
std::vector<OpRun>& op_runs();

/// steady_clock seconds around one call.
template <class F>
double time_call(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count();
}

}  // namespace tcsb::bench
