// RandomController: the node budget held by seeded random operations (RandomPolicy). The ablation of the
// perceptual feedback, and the way Table 1 is measured independently of it.
#pragma once

#include <stdexcept>

#include "../feedback/controller.h"
#include "../feedback/random_policy.h"

namespace tcsb {

/// Holds the committed cut at `target_nodes` with random refines and coarsens, at most `max_ops` begun per step.
class RandomController final : public Controller {
 public:
  RandomController(int target_nodes, int max_ops, std::uint64_t seed)
      : policy_(seed), target_(target_nodes), max_ops_(max_ops) {}
  void before_step(TcSoftBody& body) override {
    // TcSettings::exact_order: the policy picks nodes by their place in the array, so it picks from the settled
    // order (advance_blends() may have left that to its caller), and the operations it begins are settled after.
    body.settle_order();
    policy_.apply(body, target_, max_ops_);
    body.settle_order();
  }
  void set_budget(int nodes) override {
    if (nodes < 1) throw std::invalid_argument("set_budget: the node budget must be >= 1");
    target_ = nodes;
  }
  int budget() const { return target_; }

 private:
  RandomPolicy policy_;
  int target_;
  int max_ops_;
};

}  // namespace tcsb
