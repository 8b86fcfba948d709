#include "paper/world_equal_error.h"

#include <algorithm>

#include "analysis/equal_error.h"
#include "analysis/statistics.h"

namespace tcsb {

namespace {

bool ran_to_the_end(const WorldMethodResult& m) { return m.status == "ok"; }

/// Why the scene has no equal-error rows, or empty when its curves are complete.
std::string missing_world_curve(const std::vector<TimedCurvePoint>& tcsb, const std::vector<TimedCurvePoint>& lod,
                                const std::vector<TimedCurvePoint>& full) {
  if (tcsb.empty()) return "tcsb_world ran to the end at no budget (it runs with feedback.budget_scope \"world\")";
  if (lod.size() < 2) return "discrete LOD ran to the end at no budget";
  if (full.size() < 2)
    return "no full-resolution scene at fewer passes ran to the end (fidelity.curves.solver_divisors)";
  return "";
}

void fill_world_curves(const WorldResult& result, const WorldMethodResult& floor, std::uint64_t seed,
                       EqualErrorNet& scene) {
  const WorldMethodResult& reference = result.methods.front();
  if (!ran_to_the_end(floor) || !(floor.p95_px > 0)) {
    scene.missing = "no noise floor (the perturbed reference diverged): the reference's point on the curves is its "
                    "noise floor";
    return;
  }
  const std::vector<double>& reference_blocks = reference.block_step_ms;
  if (reference_blocks.empty()) {
    scene.missing = "the reference's blocks were not timed (it diverged)";
    return;
  }
  scene.floor = floor.p95_px;
  std::vector<TimedCurvePoint> tcsb, lod, full;
  for (const WorldMethodResult& m : result.methods) {
    if (&m == &reference || !ran_to_the_end(m) || m.block_step_ms.size() != reference_blocks.size()) continue;
    // Below the noise floor an error is not resolved; the floor keeps the log-log curves defined.
    const TimedCurvePoint p{{.method = m.method,
                             .compression = m.budget,
                             .solver_divisor = m.solver_divisor,
                             .nodes = m.mean_nodes,
                             .time_ms = median(m.block_step_ms),
                             .error = std::max(m.p95_px, scene.floor)},
                            &m.block_step_ms};
    if (m.method == "tcsb_world") tcsb.push_back(p);
    if (m.method == "discrete_lod") lod.push_back(p);
    if (m.method == "full_resolution") full.push_back(p);
  }
  const TimedCurvePoint top{
      {.method = "reference", .nodes = reference.mean_nodes, .time_ms = median(reference_blocks), .error = scene.floor},
      &reference_blocks};
  lod.push_back(top);
  full.push_back(top);
  scene.missing = missing_world_curve(tcsb, lod, full);
  if (scene.missing.empty())
    fill_equal_error(std::move(tcsb), std::move(lod), std::move(full), reference_blocks.size(), seed, scene);
}

std::vector<WorldSameNodesRow> same_nodes_rows(const WorldResult& result) {
  std::vector<NodesPoint> body_curve;
  for (const WorldMethodResult& m : result.methods)
    if (m.method == "tcsb_body" && ran_to_the_end(m) && m.mean_nodes > 0 && m.p95_px > 0 &&
        std::none_of(body_curve.begin(), body_curve.end(),
                     [&](const NodesPoint& p) { return p.nodes == m.mean_nodes; }))
      body_curve.push_back({m.mean_nodes, m.p95_px});
  std::vector<WorldSameNodesRow> rows;
  for (const WorldMethodResult& m : result.methods) {
    if (m.method != "tcsb_world" || !ran_to_the_end(m)) continue;
    WorldSameNodesRow row;
    row.budget = m.budget;
    row.nodes = m.mean_nodes;
    row.world_p95_px = m.p95_px;
    if (!body_curve.empty() && m.mean_nodes > 0) row.body_p95_px = error_at_nodes(body_curve, m.mean_nodes);
    if (row.body_p95_px && m.p95_px > 0) row.ratio = *row.body_p95_px / m.p95_px;
    rows.push_back(row);
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const WorldSameNodesRow& a, const WorldSameNodesRow& b) { return a.budget < b.budget; });
  return rows;
}

}  // namespace

std::optional<WorldEqualError> world_equal_error(const WorldResult& result, std::uint64_t seed) {
  const auto floor = std::find_if(result.methods.begin(), result.methods.end(),
                                  [](const WorldMethodResult& m) { return m.method == "noise_floor"; });
  if (floor == result.methods.end()) return std::nullopt;
  WorldEqualError out;
  out.scene.net = "scene";
  out.scene.metric = "p95_px";
  fill_world_curves(result, *floor, seed, out.scene);
  out.same_nodes = same_nodes_rows(result);
  return out;
}

}  // namespace tcsb
