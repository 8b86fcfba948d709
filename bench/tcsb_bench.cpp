// tcsb_bench: Google Benchmark micro-benchmarks of the TreeCut soft body (op_bench.cpp: one operation at a time;
// step_bench.cpp: one step). This file holds the shared fixtures and main(), which after the benchmarks prints a
// flatness summary of the per-operation costs against the body's size to stderr (stdout stays the benchmark
// library's, so --benchmark_format=json still yields clean JSON).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/linear_fit.h"
#include "analysis/statistics.h"
#include "bench_bodies.h"
#include "feedback/random_policy.h"

namespace tcsb::bench {

std::shared_ptr<const Net> square_net(int width) {
  NetSpec spec;
  spec.name = "bench" + std::to_string(width);
  spec.width = spec.height = width;
  spec.size_x = spec.size_z = 8.0;
  spec.elevation = 8.0;
  spec.mass_mode = MassMode::kTotal;
  spec.mass = 1.0;
  spec.pinned_corners = kAllCorners;
  return std::make_shared<const Net>(spec);
}

SolverSettings bench_solver() {
  SolverSettings s;
  s.piterations = 2;
  return s;
}

namespace {
/// Gravity steps taken while the cut settles: enough to set the cloth swinging, few enough that the 513^2 body's
/// setup stays within seconds (a step there costs ~0.1-0.3 s).
int setup_steps_for(int width) { return width <= 65 ? 40 : width <= 129 ? 20 : width <= 257 ? 10 : 5; }
}  // namespace

OpBody::OpBody(int w)
    : width(w), world(WorldSettings{}), net(square_net(w)), rng(0x7c5b0000ULL + static_cast<unsigned>(w)) {
  const auto t0 = std::chrono::steady_clock::now();
  // About 1 s at 513^2 (the node DBVT is built in a shuffled order: init_net_nodes), 3 s with the cut and steps below;
  // the body is therefore built once per width and process.
  body = std::make_unique<TcSoftBody>(world.info(), net, bench_solver(), TcSettings{});
  const auto tc = std::chrono::steady_clock::now();
  RandomPolicy policy(20240000ULL + static_cast<unsigned>(w));
  const int n = static_cast<int>(net->node_count());
  const int target = n / 2;
  // 1. Operations only (cheap even at 513^2): bursts of random coarse/refine until the committed cut is near half
  //    the grid. Each round is a step boundary, so blends finish as they would in a run. Bursts shrink as the cut
  //    nears the target, so it does not overshoot and swing around it.
  int rounds = 0;
  for (; rounds < 4000 && std::abs(body->committed_count() - target) > std::max(8, n / 200); ++rounds) {
    body->advance_blends();
    const int burst = std::clamp(std::abs(body->committed_count() - target) / 6, 16, std::max(64, n / 64));
    policy.apply(*body, target, burst);
  }
  // 2. Swing under gravity with operations still flowing at the target, so the cut is a random mixture and the
  //    nodes move.
  const auto t1 = std::chrono::steady_clock::now();
  setup_steps = setup_steps_for(w);
  for (int s = 0; s < setup_steps; ++s) {
    body->advance_blends();
    policy.apply(*body, target, std::max(4, n / 2048));
    body->simulate_step(kDt);
  }
  // 3. Let every blend end: the benchmarks need exactly one operation in flight at a time.
  for (int k = 0; k < body->settings().blend_steps; ++k) body->advance_blends();
  if (body->interpolations() != 0) throw std::logic_error("OpBody: blends did not finish");
  const auto t2 = std::chrono::steady_clock::now();
  const Validation v = body->validate();
  if (!v.ok()) throw std::logic_error("OpBody: invalid body after setup: " + v.summary());
  setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto secs = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::fprintf(stderr,
               "[setup] width %d: %d grid nodes -> %d Bullet nodes, %d links after %d steps; %.2f s (construct %.2f, "
               "cut %.2f in %d rounds, steps %.2f)\n",
               w, n, body->node_count(), body->link_count(), setup_steps, setup_seconds, secs(t0, tc), secs(tc, t1),
               rounds, secs(t1, t2));
}

TreeId OpBody::coarse_candidate(int attempts) {
  for (int a = 0; a < attempts; ++a) {
    std::uniform_int_distribution<int> pick(0, body->node_count() - 1);
    const TreeId parent = body->tree().node(body->tree_id(pick(rng))).parent;
    if (parent != kNoTreeNode && body->can_coarsen(parent).ok) return parent;
  }
  return kNoTreeNode;
}

TreeId OpBody::refine_candidate(int attempts) {
  for (int a = 0; a < attempts; ++a) {
    std::uniform_int_distribution<int> pick(0, body->node_count() - 1);
    const TreeId id = body->tree_id(pick(rng));
    if (body->can_refine(id).ok) return id;
  }
  return kNoTreeNode;
}

OpBody& op_body(int width) {
  static std::map<int, std::unique_ptr<OpBody>> cache;
  auto& slot = cache[width];
  if (!slot) slot = std::make_unique<OpBody>(width);
  return *slot;
}

std::vector<OpRun>& op_runs() {
  static std::vector<OpRun> runs;
  return runs;
}

namespace {

/// TCSB_BENCH_OP_ITERS read: kOpIterations when unset, its value when a positive whole number, else nullopt.
std::optional<int> op_iterations_setting() {
  const char* env = std::getenv("TCSB_BENCH_OP_ITERS");
  if (env == nullptr) return kOpIterations;
  const std::string_view text(env);
  int n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || n <= 0) return std::nullopt;
  return n;
}

}  // namespace

std::optional<std::string> op_iterations_error() {
  if (op_iterations_setting()) return std::nullopt;
  return "TCSB_BENCH_OP_ITERS: expected a positive whole number of calls, got \"" +
         std::string(std::getenv("TCSB_BENCH_OP_ITERS")) + "\"";
}

// Read at benchmark registration (static initialisation); a bad value is reported by main() before anything runs.
int op_iterations() { return op_iterations_setting().value_or(kOpIterations); }

namespace {

/// One benchmark at one size, its repetitions pooled.
struct SizeSummary {
  int width = 0;
  long long nodes = 0;  ///< mean over the repetitions (the cut is restored after each call, so they agree)
  int repetitions = 0;
  std::size_t calls = 0;
  double median_ns = 0, mean_ns = 0, p90_ns = 0, p99_ns = 0, max_ns = 0;
  double node_median_ns = 0, link_median_ns = 0;
  double rep_median_lo = 0, rep_median_hi = 0;  ///< range of the repetitions' own medians: the drift between them
};

SizeSummary pool(const std::vector<const OpRun*>& reps) {
  SizeSummary s;
  s.width = reps.front()->width;
  s.repetitions = static_cast<int>(reps.size());
  std::vector<double> ns, node_ns, link_ns, rep_medians;
  double nodes = 0;
  for (const OpRun* r : reps) {
    ns.insert(ns.end(), r->ns.begin(), r->ns.end());
    node_ns.insert(node_ns.end(), r->node_ns.begin(), r->node_ns.end());
    link_ns.insert(link_ns.end(), r->link_ns.begin(), r->link_ns.end());
    rep_medians.push_back(median(r->ns));
    nodes += static_cast<double>(r->nodes);
  }
  s.nodes = std::llround(nodes / static_cast<double>(reps.size()));
  s.calls = ns.size();
  if (ns.empty()) return s;
  s.mean_ns = mean(ns);
  s.median_ns = median(ns);
  s.p90_ns = percentile(ns, 90);
  s.p99_ns = percentile(ns, 99);
  s.max_ns = *std::max_element(ns.begin(), ns.end());
  s.node_median_ns = median(node_ns);
  s.link_median_ns = median(link_ns);
  s.rep_median_lo = *std::min_element(rep_medians.begin(), rep_medians.end());
  s.rep_median_hi = *std::max_element(rep_medians.begin(), rep_medians.end());
  return s;
}

/// Per op: the per-size medians (repetitions pooled), an ordinary least-squares line through (N, median ns), and
/// the target check "slope x (largest N - smallest N) < 20% of the median cost" (the median of the per-size
/// medians).
void print_summary() {
  const auto& runs = op_runs();
  if (runs.empty()) return;
  std::map<std::string, std::map<int, std::vector<const OpRun*>>> by_op;
  std::vector<std::string> order;
  for (const OpRun& r : runs) {
    if (!by_op.count(r.op)) order.push_back(r.op);
    by_op[r.op][r.width].push_back(&r);
  }
  // Canonical order, whatever order the interleaving ran them in.
  const std::vector<std::string> canonical{"BM_Refine", "BM_EndRefine", "BM_Coarse", "BM_EndCoarse"};
  const auto rank = [&](const std::string& op) { return std::find(canonical.begin(), canonical.end(), op); };
  std::stable_sort(order.begin(), order.end(),
                   [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  std::map<std::string, std::vector<SizeSummary>> sizes;
  for (const std::string& op : order)
    for (const auto& [width, reps] : by_op[op]) sizes[op].push_back(pool(reps));

  std::fprintf(stderr, "\nPer-operation cost (ns, one call; N = Bullet nodes at the mixed cut; repetitions pooled, "
                       "rep medians = the range of their own medians)\n");
  std::fprintf(stderr, "%-14s %6s %8s %4s %7s %9s %9s %9s %9s %9s %9s %9s %15s\n", "op", "width", "N", "reps", "calls",
               "median", "mean", "p90", "p99", "max", "node_med", "link_med", "rep medians");
  for (const std::string& op : order)
    for (const SizeSummary& z : sizes[op])
      std::fprintf(stderr, "%-14s %6d %8lld %4d %7zu %9.0f %9.0f %9.0f %9.0f %9.0f %9.0f %9.0f %7.0f-%-7.0f\n",
                   op.c_str(), z.width, z.nodes, z.repetitions, z.calls, z.median_ns, z.mean_ns, z.p90_ns, z.p99_ns,
                   z.max_ns, z.node_median_ns, z.link_median_ns, z.rep_median_lo, z.rep_median_hi);
  std::fprintf(stderr, "\nFlatness in N (OLS of per-size median ns on N; target |slope x (Nmax-Nmin)| < 20%% of the "
                       "median cost)\n");
  std::fprintf(stderr, "%-14s %5s %8s %8s %12s %12s %10s %8s  %s\n", "op", "sizes", "Nmin", "Nmax", "slope ns/N",
               "slope*dN ns", "median ns", "ratio", "verdict");
  for (const std::string& op : order) {
    const auto& zs = sizes[op];
    std::vector<double> nodes, medians;
    for (const SizeSummary& z : zs) {
      nodes.push_back(static_cast<double>(z.nodes));
      medians.push_back(z.median_ns);
    }
    const double nmin = *std::min_element(nodes.begin(), nodes.end());
    const double nmax = *std::max_element(nodes.begin(), nodes.end());
    const double cost = median(medians);
    const LinearFit fit = fit_linear(nodes, medians);
    if (!fit.valid) {
      std::fprintf(stderr, "%-14s %5zu %8.0f %8.0f %12s %12s %10.0f %8s  %s\n", op.c_str(), zs.size(), nmin, nmax, "-",
                   "-", cost, "-", "needs 2+ sizes");
      continue;
    }
    const double spread = fit.slope * (nmax - nmin);
    const double ratio = cost > 0 ? spread / cost : 0.0;
    const char* verdict = std::fabs(ratio) < 0.2 ? "flat" : (ratio > 0 ? "GROWS" : "falls");
    std::fprintf(stderr, "%-14s %5zu %8.0f %8.0f %12.3e %12.1f %10.0f %7.1f%%  %s\n", op.c_str(), zs.size(), nmin, nmax,
                 fit.slope, spread, cost, 100.0 * ratio, verdict);
  }
  // The median target is stated at 65x65.
  for (const std::string& op : order)
    for (const SizeSummary& z : sizes[op])
      if (z.width == 65)
        std::fprintf(stderr, "%-14s at 65x65: median %.0f ns (target <= 2000 ns): %s\n", op.c_str(), z.median_ns,
                     z.median_ns <= 2000 ? "met" : "MISSED");
}

/// The command line with this benchmark's defaults in front: kDefaultRepetitions repetitions, randomly
/// interleaved, aggregates only on the console (a --benchmark_out file still gets every repetition). Flags the
/// user gives come later and so win.
std::vector<char*> with_defaults(int argc, char** argv) {
  static std::string repetitions = "--benchmark_repetitions=" + std::to_string(kDefaultRepetitions);
  static std::string interleave = "--benchmark_enable_random_interleaving=true";
  static std::string aggregates = "--benchmark_display_aggregates_only=true";
  std::vector<char*> args{argv[0], repetitions.data(), interleave.data(), aggregates.data()};
  for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  return args;
}

}  // namespace
}  // namespace tcsb::bench

int main(int argc, char** argv) {
  std::vector<char*> args = tcsb::bench::with_defaults(argc, argv);
  int count = static_cast<int>(args.size()) - 1;
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 2;  // bad input: the project's exit code
  if (const std::optional<std::string> error = tcsb::bench::op_iterations_error()) {
    std::fprintf(stderr, "tcsb_bench: %s\n", error->c_str());
    return 2;
  }
  benchmark::RunSpecifiedBenchmarks();
  tcsb::bench::print_summary();
  benchmark::Shutdown();
  return 0;
}
