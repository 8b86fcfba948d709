#include "report/world_json.h"

#include <optional>

#include "paper/world_equal_error.h"
#include "report/equal_error_json.h"
#include "report/json_number.h"

namespace tcsb {

namespace {

using ojson = nlohmann::ordered_json;

void add_world_equal_error(const WorldEqualError& table, ojson& world) {
  ojson same_nodes = ojson::array();
  for (const WorldSameNodesRow& r : table.same_nodes)
    same_nodes.push_back({{"budget", json_number(r.budget)},
                          {"N", json_number(r.nodes)},
                          {"tcsb_world_p95_px", json_number(r.world_p95_px)},
                          {"tcsb_body_p95_px", json_number(r.body_p95_px)},
                          {"body_over_world", json_number(r.ratio)}});
  world["equal_error"] = {
      {"definition",
       "the fidelity pass's speed-up at equal error on the whole scene (fidelity.curves): for tcsb_world's error at "
       "each budget (p95_px over every body, floored at the noise floor: the reference started perturbed, also the "
       "reference's point on both rival curves), the step time discrete LOD's curve across budgets and full "
       "resolution's at fewer passes need to reach it, log-log interpolated and never extrapolated; speedup = that "
       "time / tcsb_world's, times medians over the pass's interleaved blocks of 20 steps, the interval a 95 % "
       "percentile bootstrap over them"},
      {"scene", equal_error_json(table.scene, "discrete_lod")},
      {"same_nodes_definition",
       "per tcsb_world budget, tcsb_body's p95_px at tcsb_world's mean total nodes N, log-log interpolated between "
       "the two tcsb_body budgets around N (null outside its budgets); body_over_world above 1: the world budget errs "
       "less at the same total nodes"},
      {"same_nodes", std::move(same_nodes)}};
}

}  // namespace

void add_world_json(const RunResult& result, const RunTables& tables, nlohmann::ordered_json& doc) {
  if (!result.world) return;
  const WorldResult& w = *result.world;
  ojson methods = ojson::array();
  for (const WorldMethodResult& m : w.methods) {
    ojson body_nodes = ojson::array();
    for (const double n : m.body_mean_nodes) body_nodes.push_back(json_number(n));
    ojson row = {{"method", m.method},
                 {"budget", json_number(m.budget)},
                 {"status", m.status},
                 {"mean_nodes", json_number(m.mean_nodes)},
                 {"body_mean_nodes", std::move(body_nodes)},
                 {"step_ms", json_number(m.step_ms)},
                 {"boundary_ms", json_number(m.boundary_ms)},
                 {"step_ratio", json_number(m.step_ratio)},
                 {"p95_px", json_number(m.p95_px)},
                 {"popping_px", json_number(m.popping_px)},
                 {"resolution_changes", m.resolution_changes}};
    if (m.diverged_step) {
      row["diverged_step"] = *m.diverged_step;
      row["diverged_reason"] = m.diverged_reason;
    }
    if (m.lod_scale) row["lod_scale_m"] = json_number(*m.lod_scale);
    if (m.churn)
      row["operations"] = {{"refines", m.churn->refines},
                           {"coarsens", m.churn->coarsens},
                           {"undone", m.churn->undone},
                           {"reversals", m.churn->reversals},
                           {"nodes_moved", m.churn->nodes_moved}};
    if (m.solver_divisor != 1) row["solver_divisor"] = m.solver_divisor;
    methods.push_back(std::move(row));
  }
  doc["world"] = {{"bodies", w.bodies},
                  {"scene_nodes", w.scene_nodes},
                  {"wall_s", json_number(w.wall_s)},
                  {"methods", std::move(methods)}};
  // Only when set, so results written before the setting read as before.
  if (const std::optional<int> g = result.suite.fidelity.geomorph_boundaries) doc["world"]["geomorph_boundaries"] = *g;
  if (tables.world_equal_error) add_world_equal_error(*tables.world_equal_error, doc["world"]);
}

}  // namespace tcsb
