// Test helper: the budget policy driven by a fixed salience field, evaluated afresh every step on a net without
// gravity, so whatever the cut does comes from the policy and the field alone.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "feedback/budget_policy.h"
#include "feedback/pin_tension.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"

namespace tcsb::testing {

/// A TC-SB body of `net` with default settings, in a world without gravity: it moves only as operations move it.
struct StillBody {
  explicit StillBody(std::shared_ptr<const Net> net)
      : world(without_gravity()), body(world.info(), std::move(net), {}, {}) {}
  static WorldSettings without_gravity() {
    WorldSettings settings;
    settings.gravity = 0;
    return settings;
  }
  SceneWorld world;
  TcSoftBody body;
};

/// Runs `steps` steps of `body` (a StillBody's), ranking with settings.interface_charge (weighed by
/// settings.interface_tension) and applying with the policy under `budget`; `field(tree id)` is a node's salience.
/// Checks that the body never holds more than `budget` nodes once it converged. Returns the operations begun per step.
template <class Field>
std::vector<int> run_on_fixed_field(TcSoftBody& body, const FeedbackSettings& settings, int budget, int steps,
                                    Field field, BudgetState& state) {
  CutSnapshot snapshot;
  Evaluation evaluation;
  std::vector<int> ops_per_step;
  const std::vector<float> weights = interface_weights(body.tree(), settings.interface_tension);
  for (int step = 0; step < steps; ++step) {
    body.advance_blends();
    take_snapshot(body, cut_view(body), false, step, snapshot);
    std::vector<float> s(snapshot.size());
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = field(snapshot.cut.tree_of[i]);
    rank_candidates(snapshot, s, 2 * settings.max_ops_per_step, evaluation, {}, {settings.interface_charge, weights});
    ops_per_step.push_back(apply_evaluation(body, evaluation, budget, settings, state));
    body.simulate_step(1.0f / 60);
    if (state.converged) {
      EXPECT_LE(body.node_count(), budget) << "step " << step;
    }
  }
  return ops_per_step;
}

/// Links of the body's cut between nodes of different levels, of those with an endpoint that `counted(tree id)`.
template <class Predicate>
int level_boundary_links(const TcSoftBody& body, Predicate counted) {
  int count = 0;
  for (const CutLink& link : body.cut_links())
    if (link.joins_committed() && body.tree().node(link.a).level != body.tree().node(link.b).level &&
        (counted(link.a) || counted(link.b)))
      ++count;
  return count;
}

inline int level_boundary_links(const TcSoftBody& body) {
  return level_boundary_links(body, [](TreeId) { return true; });
}

}  // namespace tcsb::testing
