#include "report/world_json.h"

#include "report/json_number.h"

namespace tcsb {

void add_world_json(const RunResult& result, nlohmann::ordered_json& doc) {
  using ojson = nlohmann::ordered_json;
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
                 {"step_ratio", json_number(m.step_ratio)},
                 {"p95_px", json_number(m.p95_px)},
                 {"popping_px", json_number(m.popping_px)},
                 {"resolution_changes", m.resolution_changes}};
    if (m.diverged_step) {
      row["diverged_step"] = *m.diverged_step;
      row["diverged_reason"] = m.diverged_reason;
    }
    if (m.lod_scale) row["lod_scale_m"] = json_number(*m.lod_scale);
    methods.push_back(std::move(row));
  }
  doc["world"] = {{"bodies", w.bodies},
                  {"scene_nodes", w.scene_nodes},
                  {"wall_s", json_number(w.wall_s)},
                  {"methods", std::move(methods)}};
}

}  // namespace tcsb
