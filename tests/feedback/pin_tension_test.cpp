// The distance of every leaf to the nearest pin (an exact distance transform), the weights it gives a block's level
// boundaries, and the controller's cut keeping its boundaries away from the pins when they weigh more there.
#include "feedback/pin_tension.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "feedback/interface_balance.h"
#include "feedback/saliency_controller.h"
#include "fixed_field.h"
#include "scene/scene_world.h"

namespace tcsb {
namespace {

std::shared_ptr<const Net> net_of(int width, int height, unsigned pinned_corners) {
  NetSpec spec;
  spec.width = width;
  spec.height = height;
  spec.pinned_corners = pinned_corners;
  return std::make_shared<const Net>(spec);
}

/// The distance by brute force: every leaf against every pinned leaf.
std::vector<double> brute_force_distances(const LodTree& tree) {
  const int w = tree.level_width(0);
  std::vector<double> out(tree.leaf_count(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t p = 0; p < out.size(); ++p)
      if (tree.nodes()[p].pinned()) {
        const double dx = static_cast<double>(static_cast<int>(i) % w - static_cast<int>(p) % w);
        const double dy = static_cast<double>(static_cast<int>(i) / w - static_cast<int>(p) / w);
        out[i] = std::min(out[i], std::sqrt(dx * dx + dy * dy));
      }
  return out;
}

TEST(PinTension, DistancesAreExactEuclidean) {
  for (const unsigned corners : {unsigned{kAllCorners}, unsigned{kCornerMaxMin},
                                 unsigned{kCornerMinMin | kCornerMaxMax}, unsigned{kCornerMinMax | kCornerMaxMax}}) {
    for (const auto& [w, h] : {std::pair{13, 9}, std::pair{9, 13}, std::pair{2, 2}, std::pair{17, 17}}) {
      const auto net = net_of(w, h, corners);
      const std::vector<float> fast = pin_distances(net->lod());
      const std::vector<double> slow = brute_force_distances(net->lod());
      ASSERT_EQ(fast.size(), slow.size());
      for (std::size_t i = 0; i < slow.size(); ++i)
        ASSERT_NEAR(fast[i], slow[i], 1e-5) << w << " x " << h << ", corners " << corners << ", leaf " << i;
    }
  }
}

TEST(PinTension, NothingPinnedOrNoTensionWeighsOne) {
  const auto free_net = net_of(17, 17, 0);
  for (const float d : pin_distances(free_net->lod())) EXPECT_TRUE(std::isinf(d));
  for (const float w : interface_weights(free_net->lod(), 0.5)) EXPECT_EQ(w, 1.0f);
  const auto pinned = net_of(17, 17, kAllCorners);
  for (const float w : interface_weights(pinned->lod(), 0.0)) EXPECT_EQ(w, 1.0f);
}

TEST(PinTension, ABlockWeighsAsItsLeafNearestToAPin) {
  const auto net = net_of(17, 17, kCornerMinMin);
  const LodTree& tree = net->lod();
  const std::vector<float> weight = interface_weights(tree, 0.5);
  const double side = 16;
  EXPECT_FLOAT_EQ(weight[static_cast<std::size_t>(tree.at(0, 0, 0))], static_cast<float>(1 + 0.5 * side / 1))
      << "on the pin: the distance counts as 1";
  EXPECT_FLOAT_EQ(weight[static_cast<std::size_t>(tree.at(0, 16, 16))],
                  static_cast<float>(1 + 0.5 * side / std::sqrt(2.0 * 16 * 16)));
  // Level-1 block (3, 2) covers leaves 6..7 x 4..5: its nearest leaf to (0, 0) is (6, 4).
  EXPECT_FLOAT_EQ(weight[static_cast<std::size_t>(tree.at(1, 3, 2))],
                  static_cast<float>(1 + 0.5 * side / std::sqrt(6.0 * 6 + 4 * 4)));
  EXPECT_FLOAT_EQ(weight[static_cast<std::size_t>(tree.root())], static_cast<float>(1 + 0.5 * side))
      << "the root holds the pin";
}

/// A 17 x 17 TC-SB body at its finest cut, pinned at grid (0, 0), and its tree's weights at tension 0.5.
struct PinnedCorner17 {
  std::shared_ptr<const Net> net = net_of(17, 17, kCornerMinMin);
  SceneWorld world{WorldSettings{}};
  TcSoftBody body{world.info(), net, {}, {}};
  std::vector<float> weight = interface_weights(body.tree(), 0.5);
};

TEST(PinTension, ABoundaryNearAPinWeighsMore) {
  const PinnedCorner17 f;
  const LodTree& tree = f.body.tree();
  const std::vector<float>& weight = f.weight;
  const CutView cut = cut_view(f.body);
  const TreeId near = tree.at(1, 1, 1), far = tree.at(1, 6, 6);  // both among leaves only: balance -4
  ASSERT_EQ(neighbour_balance(cut, near), neighbour_balance(cut, far));
  const InterfaceCharge flat{3.0, {}}, weighed{3.0, weight};
  EXPECT_DOUBLE_EQ(flat.factor(cut, near), flat.factor(cut, far));
  EXPECT_DOUBLE_EQ(weighed.factor(cut, far), std::exp(3.0 * weight[static_cast<std::size_t>(far)]));
  EXPECT_GT(weighed.factor(cut, near), weighed.factor(cut, far)) << "a coarsen among finer blocks waits longer there";
  EXPECT_DOUBLE_EQ(InterfaceCharge{}.factor(cut, near), 1.0);
}

/// A 33 x 33 net pinned at its four corners, falling under the saliency controller for 200 steps with the interface
/// charge 3 and the given pin tension and pull, at `share` of its nodes.
struct ControlledCut {
  std::shared_ptr<const Net> net;
  SceneWorld world{WorldSettings{}};
  std::unique_ptr<TcSoftBody> body;

  ControlledCut(double tension, double pull, double share) {
    NetSpec spec;
    spec.width = spec.height = 33;
    net = std::make_shared<const Net>(spec);
    body = std::make_unique<TcSoftBody>(world.info(), net, SolverSettings{}, TcSettings{});
    FeedbackSettings settings;
    settings.threshold = 0.3;
    settings.interface_charge = 3;
    settings.interface_tension = tension;
    settings.pin_level_pull = pull;
    SaliencyController controller(settings, static_cast<int>(net->node_count() * share));
    for (int step = 0; step < 200; ++step) {
      body->advance_blends();
      controller.before_step(*body);
      body->simulate_step(1.0f / 60);
      controller.after_step(*body);
    }
    EXPECT_TRUE(controller.converged());
    EXPECT_TRUE(body->validate().ok()) << body->validate().summary();
  }

  /// Is the block's nearest leaf within 8 grid steps of a pin?
  bool near_a_pin(TreeId id) const {
    static const std::vector<float> distance = pin_distances(net->lod());
    const LodNode& n = net->lod().node(id);
    return distance[static_cast<std::size_t>(n.leaf_y0 * 33 + n.leaf_x0)] < 8.0f;
  }
  /// Links of the cut between levels with an end near a pin.
  int boundaries_near_the_pins() const {
    return testing::level_boundary_links(*body, [&](TreeId id) { return near_a_pin(id); });
  }
  /// Simulated leaves (level 0) near a pin.
  int fine_nodes_near_the_pins() const {
    int count = 0;
    for (const TreeId id : body->tree_ids())
      if (net->lod().node(id).level == 0 && near_a_pin(id)) ++count;
    return count;
  }
};

TEST(PinTension, TheControllerKeepsBoundariesAwayFromThePins) {
  const int flat = ControlledCut(0.0, 0.0, 0.75).boundaries_near_the_pins();
  const int weighed = ControlledCut(0.5, 0.0, 0.75).boundaries_near_the_pins();
  EXPECT_GT(flat, 0);
  EXPECT_LT(weighed, flat) << "flat " << flat << ", weighed " << weighed;
}

TEST(PinTension, ThePullMakesThePinsTakeTheBudgetsLevel) {
  // At 30 % most of the cloth is at level 1: with the pull the pins' surroundings are too.
  const int fine = ControlledCut(0.5, 0.0, 0.3).fine_nodes_near_the_pins();
  const int pulled = ControlledCut(0.5, 8.0, 0.3).fine_nodes_near_the_pins();
  EXPECT_LT(pulled, fine) << "without the pull " << fine << ", with it " << pulled;
  // At 75 % most of it is at level 0, and the pull keeps the pins fine.
  const int fine75 = ControlledCut(0.5, 0.0, 0.75).fine_nodes_near_the_pins();
  const int pulled75 = ControlledCut(0.5, 8.0, 0.75).fine_nodes_near_the_pins();
  EXPECT_GE(pulled75, fine75) << "without the pull " << fine75 << ", with it " << pulled75;
}

TEST(PinTension, BudgetLevelIsTheLevelHoldingMostOfTheNet) {
  const auto net = net_of(17, 17, kAllCorners);
  const LodTree& tree = net->lod();
  ASSERT_EQ(tree.level_width(1), 9);  // 289, 81, 25, ... nodes in the whole cut of each level
  ASSERT_EQ(tree.level_width(2), 5);
  EXPECT_EQ(budget_level(tree, 289), 0);
  EXPECT_EQ(budget_level(tree, 1000), 0);
  EXPECT_EQ(budget_level(tree, 200), 0) << "(200 - 81) / (289 - 81) = 0.57 of the net at level 0";
  EXPECT_EQ(budget_level(tree, 150), 1) << "0.33 at level 0";
  EXPECT_EQ(budget_level(tree, 81), 1);
  EXPECT_EQ(budget_level(tree, 50), 2) << "(50 - 25) / (81 - 25) = 0.45 at level 1";
  EXPECT_EQ(budget_level(tree, 0), tree.level_count() - 1);
}

TEST(PinTension, ThePullLeansTowardsTheBudgetsLevelNearThePins) {
  const PinnedCorner17 f;
  const LodTree& tree = f.body.tree();
  const std::vector<float>& weight = f.weight;
  const CutView cut = cut_view(f.body);
  const TreeId block = tree.at(1, 1, 1);  // a coarsen candidate among leaves, near the pin
  const InterfaceCharge none{3.0, weight}, coarse{3.0, weight, 8.0, 1}, fine{3.0, weight, 8.0, 0};
  EXPECT_LT(coarse.factor(cut, block), none.factor(cut, block)) << "budget at level 1: the coarsen goes sooner";
  EXPECT_GT(fine.factor(cut, block), none.factor(cut, block)) << "budget at level 0: later";
  const double w = weight[static_cast<std::size_t>(block)];
  EXPECT_NEAR(std::log(coarse.factor(cut, block) / none.factor(cut, block)), -3.0 * 8.0 * (w - 1) / 4, 1e-9);
  const InterfaceCharge unweighed{3.0, {}, 8.0, 1};
  const InterfaceCharge flat{3.0, {}};
  EXPECT_DOUBLE_EQ(unweighed.factor(cut, block), flat.factor(cut, block)) << "no pins, no pull";
}

}  // namespace
}  // namespace tcsb
