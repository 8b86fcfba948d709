#include "suite/world_plan.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "suite/scene_bodies.h"

namespace tcsb {

std::vector<double> world_budgets(const Suite& suite) {
  std::vector<double> budgets;
  for (const double c : suite.compression)
    if (c < 1.0) budgets.push_back(c);
  if (!suite.fidelity.curves) return budgets;
  budgets.insert(budgets.end(), suite.fidelity.curves->budgets.begin(), suite.fidelity.curves->budgets.end());
  std::sort(budgets.begin(), budgets.end());
  budgets.erase(std::unique(budgets.begin(), budgets.end()), budgets.end());
  return budgets;
}

WorldTracks world_tracks(const Suite& suite) {
  if (!is_world_suite(suite)) return {};
  const int budgets = static_cast<int>(world_budgets(suite).size());
  WorldTracks t;
  t.tcsb = budgets * (suite.feedback.budget_scope == BudgetScope::kWorld ? 2 : 1);
  t.plain = 1 + budgets;
  if (suite.fidelity.curves) t.plain += 1 + static_cast<int>(suite.fidelity.curves->solver_divisors.size());
  return t;
}

std::vector<double> lod_camera_distances(const Suite& suite, int steps) {
  const Camera& camera = *suite.scene.camera;
  const double ahead = suite.feedback.view_lookahead_s;
  const std::vector<NetSpec> placed = scene_body_nets(suite);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(steps) * placed.size());
  for (int s = 0; s < steps; ++s) {
    const double t = static_cast<double>(s + 1) * suite.world.dt;
    const std::array<double, 3> now = camera.pose_at(t).position;
    const std::array<double, 3> then = ahead > 0 ? camera.pose_at(t + ahead).position : now;
    for (const NetSpec& n : placed) {
      const auto distance = [&](const std::array<double, 3>& eye) {
        return std::hypot(eye[0] - n.centre_x, eye[1] - n.elevation, eye[2] - n.centre_z);
      };
      out.push_back(std::min(distance(now), distance(then)));
    }
  }
  return out;
}

}  // namespace tcsb
