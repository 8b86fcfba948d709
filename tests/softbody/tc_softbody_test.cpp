#include "softbody/tc_softbody_impl.h"

#include <gtest/gtest.h>

#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <algorithm>
#include <random>

#include "feedback/random_policy.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "test_bodies.h"

namespace tcsb {
namespace {

using testing::kDt;

/// Steps like the runner: blends advance at the step boundary, then operations begin, then Bullet steps.
void step_with_random_ops(TcSoftBody& body, RandomPolicy& policy, int target, int ops) {
  body.advance_blends();
  policy.apply(body, target, ops);
  body.simulate_step(kDt);
}

TEST(TcSoftBody, StartsAsTheFinestCutIdenticalToPlain) {
  const auto net = testing::square_net(33);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
  EXPECT_EQ(tc.node_count(), plain->m_nodes.size());
  EXPECT_EQ(tc.link_count(), plain->m_links.size());
  EXPECT_EQ(tc.interpolations(), 0);
  const Validation v = tc.validate();
  EXPECT_TRUE(v.ok()) << v.summary();
}

TEST(TcSoftBody, WithoutOperationsMatchesPlainBitForBitAfter100Steps) {
  // With either interface: until the cut holds a level boundary, a hanging-interface body's constraint solve is
  // Bullet's own.
  for (const Interfaces interfaces : {Interfaces::kLinks, Interfaces::kHanging}) {
    const auto net = testing::square_net(33);
    SceneWorld world({});
    TcSettings settings;
    settings.interfaces = interfaces;
    TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
    auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
    for (int s = 0; s < 100; ++s) {
      tc.advance_blends();
      tc.simulate_step(kDt);
      step_soft_body(*plain, kDt);
    }
    for (int i = 0; i < plain->m_nodes.size(); ++i) {
      ASSERT_EQ(tc.m_nodes[i].m_x, plain->m_nodes[i].m_x) << "node " << i;
      ASSERT_EQ(tc.m_nodes[i].m_v, plain->m_nodes[i].m_v) << "node " << i;
    }
  }
}

TEST(TcSoftBody, RefineAndCoarseOfOneBlockRoundTrip) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  const TreeId parent = net->lod().at(1, 3, 3);
  ASSERT_TRUE(tc.can_coarsen(parent).ok);
  tc.begin_coarse(parent);
  EXPECT_EQ(tc.interpolations(), 1);
  EXPECT_EQ(tc.node_count(), 17 * 17 + 1);
  EXPECT_EQ(tc.committed_count(), 17 * 17 - 3);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  for (int s = 0; s < tc.settings().blend_steps; ++s) {
    tc.advance_blends();
    EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
    tc.simulate_step(kDt);
  }
  EXPECT_EQ(tc.interpolations(), 0);
  EXPECT_EQ(tc.node_count(), 17 * 17 - 3);
  EXPECT_EQ(tc.state(parent), CutState::kActive);
  ASSERT_TRUE(tc.can_refine(parent).ok);
  tc.begin_refine(parent);
  for (int s = 0; s < tc.settings().blend_steps; ++s) tc.advance_blends();
  EXPECT_EQ(tc.node_count(), 17 * 17);
  EXPECT_EQ(tc.link_count(), 2 * 17 * 16);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

TEST(TcSoftBody, UnderThePapersRuleArrivingNodesAreOutOfCollisionsUntilTheirOperationEnds) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSettings settings;
  settings.arrivals_collide = false;
  TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
  const TreeId parent = net->lod().at(1, 3, 3);
  const auto out_of_collisions = [&](TreeId id) { return tc.m_nodes[tc.bullet_index(id)].m_battach != 0; };
  tc.begin_coarse(parent);
  EXPECT_TRUE(out_of_collisions(parent));  // arriving
  const TreeId child = net->lod().node(parent).children[0];
  EXPECT_FALSE(out_of_collisions(child));  // leaving: collides until it goes
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  for (int s = 0; s < tc.settings().blend_steps; ++s) tc.advance_blends();
  EXPECT_EQ(tc.state(parent), CutState::kActive);
  EXPECT_FALSE(out_of_collisions(parent));
  tc.begin_refine(parent);
  EXPECT_TRUE(out_of_collisions(child));
  EXPECT_FALSE(out_of_collisions(parent));
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  for (int s = 0; s < tc.settings().blend_steps; ++s) tc.advance_blends();
  EXPECT_FALSE(out_of_collisions(child));
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
  tc.m_nodes[tc.bullet_index(child)].m_battach = 1;  // a committed node taken out of collisions
  const Validation broken = tc.validate();
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.summary().find("out of collisions (m_battach) but no anchor holds it"), std::string::npos)
      << broken.summary();
}

TEST(TcSoftBody, AnAnchoredNodeStaysInTheCutAndValidateWatchesItsAnchor) {
  // Bullet's anchors (a node attached to a rigid body) hold a Node*: an operation that removed the node would move
  // the anchor to whichever node takes its slot, silently.
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  btSphereShape shape(0.1f);
  btRigidBody rigid(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &shape));
  const TreeId leaf = net->index(6, 6);
  tc.appendAnchor(tc.bullet_index(leaf), &rigid);
  EXPECT_TRUE(tc.anchored(leaf));
  const TreeId parent = net->lod().node(leaf).parent;
  EXPECT_FALSE(tc.can_coarsen(parent).ok);                 // its block cannot merge
  EXPECT_TRUE(tc.can_coarsen(net->lod().at(1, 1, 1)).ok);  // others can
  RandomPolicy policy(11);
  for (int step = 0; step < 200; ++step) {
    tc.advance_blends();
    policy.apply(tc, 120, 8);
    tc.simulate_step(kDt);
    ASSERT_TRUE(tc.validate().ok()) << "step " << step << ": " << tc.validate().summary();
  }
  ASSERT_GE(tc.bullet_index(leaf), 0);
  EXPECT_EQ(tc.m_anchors[0].m_node, &tc.m_nodes[tc.bullet_index(leaf)]);  // still the node it was made for
  EXPECT_LT(tc.node_count(), 17 * 17);                                    // while the rest of the cut changed
  tc.m_anchors[0].m_node = tc.m_nodes.size() > 0 ? &tc.m_nodes[0] + tc.m_nodes.size() : nullptr;  // past the nodes
  const Validation broken = tc.validate();
  ASSERT_FALSE(broken.ok());
  // (The node it was made for is then flagged too: out of collisions, as Bullet's anchors leave it, unanchored.)
  // Named as the anchor's fault, first.
  EXPECT_EQ(broken.problems.front().rfind("anchor 0: points at no simulated node", 0), 0u) << broken.summary();
}

TEST(TcSoftBody, BalanceForbidsNeighboursTwoLevelsApart) {
  const auto net = testing::square_net(17);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  const LodTree& lod = net->lod();
  // Coarsen the four level-1 blocks under one level-2 node, then that node.
  const TreeId top = lod.at(2, 1, 1);
  for (int i = 0; i < 4; ++i) {
    const TreeId child = lod.node(top).children[static_cast<std::size_t>(i)];
    ASSERT_TRUE(tc.can_coarsen(child).ok);
    tc.begin_coarse(child);
    // The block beside it (children 0 and 1 share an edge) may not start while it blends.
    if (i == 0) {
      EXPECT_FALSE(tc.can_coarsen(lod.node(top).children[static_cast<std::size_t>(i + 1)]).ok);
    }
    for (int s = 0; s < tc.settings().blend_steps; ++s) tc.advance_blends();
  }
  EXPECT_FALSE(tc.can_coarsen(top).ok) << "its leaf neighbours would be two levels below";
  // A leaf beside the coarse block cannot be merged into a level-1 node either... but a level-1 neighbour can:
  const TreeId beside = lod.at(1, 4, 2);
  ASSERT_TRUE(tc.can_coarsen(beside).ok);
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

TEST(TcSoftBody, EachOperationConservesMassAndLinearMomentum) {
  // With block masses, and with masses that follow the cut, where operations also move mass between a block and its
  // neighbours (tc_cut_masses.cpp): a block and then its neighbour, so that the second moves mass across a boundary
  // between levels.
  for (const Masses masses : {Masses::kBlocks, Masses::kCut}) {
    SCOPED_TRACE(masses == Masses::kCut ? "cut masses" : "block masses");
    const RestPlacement rest = masses == Masses::kCut ? RestPlacement::kVertex : RestPlacement::kCentroid;
    const auto net = testing::square_net(33, 0, rest);  // no pins: momentum is conserved only away from anchors
    SceneWorld world({});
    TcSettings settings;
    settings.masses = masses;
    TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
    for (int s = 0; s < 20; ++s) tc.simulate_step(kDt);  // get it moving
    const LodTree& lod = net->lod();
    const auto check = [&](const char* what, auto&& op) {
      const Eigen::Vector3d before = tc.linear_momentum();
      const double mass_before = tc.total_mass();
      op();
      const Eigen::Vector3d after = tc.linear_momentum();
      EXPECT_LT((after - before).norm(), 1e-5 * std::max(1.0, before.norm())) << what;
      EXPECT_NEAR(tc.total_mass(), mass_before, 1e-9) << what;
      EXPECT_TRUE(tc.validate().ok()) << what << ": " << tc.validate().summary();
    };
    const auto blend_and_end = [&](const char* what) {
      tc.simulate_step(kDt);
      for (int s = 0; s < tc.settings().blend_steps - 1; ++s) tc.advance_blends();
      check(what, [&] { tc.advance_blends(); });
    };
    const TreeId p = lod.at(1, 5, 5), q = lod.at(1, 6, 5);
    check("coarse", [&] { tc.begin_coarse(p); });
    blend_and_end("end-coarse");
    ASSERT_EQ(tc.state(p), CutState::kActive);
    check("coarse beside", [&] { tc.begin_coarse(q); });
    blend_and_end("end-coarse beside");
    tc.simulate_step(kDt);
    check("refine", [&] { tc.begin_refine(p); });
    blend_and_end("end-refine");
    EXPECT_EQ(tc.state(p), CutState::kOff);
  }
}

TEST(TcSoftBody, FlatNetAtRestStaysAtRestThroughOperations) {
  WorldSettings no_gravity;
  no_gravity.gravity = 0;
  SceneWorld world(no_gravity);
  for (const RestPlacement rest : {RestPlacement::kCentroid, RestPlacement::kVertex})
    for (Placement placement : {Placement::kAffine, Placement::kRigid}) {
      SCOPED_TRACE(rest == RestPlacement::kVertex ? "vertex" : "centroid");
      const auto net = testing::square_net(33, kAllCorners, rest);
      TcSettings settings;
      settings.placement = placement;
      TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
      RandomPolicy policy(7);
      for (int s = 0; s < 600; ++s) {
        const int target = (s / 100) % 2 == 0 ? 300 : 1000;  // swing between coarse and fine cuts
        step_with_random_ops(tc, policy, target, 16);
      }
      double drift = 0;
      for (int i = 0; i < tc.node_count(); ++i) {
        const TreeId id = tc.tree_id(i);
        const Eigen::Vector3d& rest = net->lod().rest(id);
        const btVector3& x = tc.m_nodes[i].m_x;
        drift = std::max(drift, (Eigen::Vector3d(x.x(), x.y(), x.z()) - rest).norm());
      }
      EXPECT_LT(drift, 1e-5 * net->extent());
      EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
    }
}

TEST(TcSoftBody, CoarseNodesAppearAtTheirRestPositionsOnANetAtRest) {
  // Whole level-1, then level-2 cuts of a net at rest: every node, on the border too (where it rests on the border,
  // not at its block's centre of mass), appears at its rest position, so no link starts stretched.
  for (const RestPlacement rest : {RestPlacement::kCentroid, RestPlacement::kVertex})
    for (const int side : {33, 34}) {
      SCOPED_TRACE(std::to_string(side) + (rest == RestPlacement::kVertex ? " vertex" : " centroid"));
      const auto net = testing::square_net(side, kAllCorners, rest);
      SceneWorld world({});
      TcSoftBody tc(world.info(), net, testing::test_solver(), {});
      const LodTree& tree = tc.tree();
      for (int level = 1; level <= 2; ++level) {
        for (bool began = true; began;) {
          began = false;
          for (int gy = 0; gy < tree.level_height(level); ++gy)
            for (int gx = 0; gx < tree.level_width(level); ++gx)
              if (tc.can_coarsen(tree.at(level, gx, gy)).ok) {
                tc.begin_coarse(tree.at(level, gx, gy));
                began = true;
              }
          while (tc.interpolations() > 0) tc.advance_blends();
        }
        ASSERT_EQ(tc.node_count(), tree.level_width(level) * tree.level_height(level)) << "level " << level;
        int on_border = 0;
        for (int i = 0; i < tc.node_count(); ++i) {
          const TreeId id = tc.tree_id(i);
          const btVector3& x = tc.m_nodes[i].m_x;
          EXPECT_LT((Eigen::Vector3d(x.x(), x.y(), x.z()) - tree.rest(id)).norm(), 1e-6 * net->extent())
              << "level " << level << " node " << id;
          on_border += tree.rest(id) != tree.centroid(id) && !tree.node(id).pinned();
        }
        EXPECT_GT(on_border, 0);
        EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
      }
    }
}

TEST(TcSoftBody, RefiningEverythingBackGivesThePlainCounts) {
  const auto net = testing::square_net(33);
  SceneWorld world({});
  TcSoftBody tc(world.info(), net, testing::test_solver(), {});
  RandomPolicy policy(3);
  for (int s = 0; s < 150; ++s) step_with_random_ops(tc, policy, 250, 32);
  ASSERT_LT(tc.committed_count(), 400);
  // Refine until the finest cut: always possible because a blocked refine names the neighbour to refine first.
  for (int round = 0; round < 2000 && tc.committed_count() < 33 * 33; ++round) {
    tc.advance_blends();
    for (int i = 0; i < tc.node_count(); ++i) {
      const TreeId id = tc.tree_id(i);
      const OpCheck check = tc.can_refine(id);
      if (check.ok) tc.begin_refine(id);
    }
    tc.simulate_step(kDt);
  }
  for (int s = 0; s < tc.settings().blend_steps; ++s) tc.advance_blends();
  auto plain = make_plain_softbody(world.info(), *net, testing::test_solver());
  EXPECT_EQ(tc.node_count(), plain->m_nodes.size());
  EXPECT_EQ(tc.link_count(), plain->m_links.size());
  EXPECT_TRUE(tc.validate().ok()) << tc.validate().summary();
}

/// Random operations on a 65^2 net until `total` have begun or ended, validating every 20 steps; returns the
/// largest number of interface constraints seen at a check.
std::size_t random_operations_keep_every_invariant(Interfaces interfaces, long total,
                                                   RestPlacement rest = RestPlacement::kCentroid,
                                                   Masses masses = Masses::kBlocks, bool exact_order = false) {
  const auto net = testing::square_net(65, kAllCorners, rest);
  SceneWorld world({});
  TcSettings settings;
  settings.interfaces = interfaces;
  settings.masses = masses;
  settings.blend_steps = 3;
  settings.restore_order_min_nodes = 0;  // restore_order() between the operations too, whatever the body's size
  settings.exact_order = exact_order;
  TcSoftBody tc(world.info(), net, testing::test_solver(), settings);
  RandomPolicy policy(20261122);
  std::mt19937 rng(5);
  // Every array was reserved for the whole tree at construction: no operation may reallocate one (that would be
  // O(N) work, and would leave Bullet's raw Node* dangling).
  const void* const nodes = &tc.m_nodes[0];
  const void* const links = &tc.m_links[0];
  const void* const tree_ids = tc.tree_ids().data();
  const void* const cut_links = tc.cut_links().data();
  long operations = 0;
  int step = 0;
  int batches = 0;
  std::size_t most_interfaces = 0;
  while (operations < total) {
    // Targets wander over the whole range so every kind of cut, balance case and pinned block is reached.
    const int target = 300 + static_cast<int>(rng() % 4000);
    for (int s = 0; s < 20; ++s, ++step) {
      const int before = tc.interpolations();
      tc.advance_blends();
      const int ended = before - tc.interpolations();
      const int begun = policy.apply(tc, target, 64);
      operations += begun + ended;
      tc.simulate_step(kDt);
    }
    ++batches;
    const Validation v = tc.validate();
    EXPECT_TRUE(v.ok()) << "after step " << step << ": " << v.summary();
    if (!v.ok()) return most_interfaces;
    most_interfaces = std::max(most_interfaces, tc.impl().interface_constraints().size());
  }
  EXPECT_GE(operations, total);
  EXPECT_GT(tc.impl().order_restorations(), 0);
  EXPECT_EQ(tc.impl().link_reallocations(), 0);
  EXPECT_EQ(&tc.m_nodes[0], nodes);
  EXPECT_EQ(&tc.m_links[0], links);
  EXPECT_EQ(tc.tree_ids().data(), tree_ids);
  EXPECT_EQ(tc.cut_links().data(), cut_links);
  ::testing::Test::RecordProperty("steps", step);
  ::testing::Test::RecordProperty("batches", batches);
  return most_interfaces;
}

TEST(TcSoftBodyProperty, HundredThousandRandomOperationsKeepEveryInvariant) {
  EXPECT_EQ(random_operations_keep_every_invariant(Interfaces::kLinks, 100000), 0u);
}

TEST(TcSoftBodyProperty, WithHangingInterfacesRandomOperationsKeepEveryInvariant) {
  // validate() checks the constraints too: handles, siblings, rest distances, one per coarse side, no fan left.
  EXPECT_GT(random_operations_keep_every_invariant(Interfaces::kHanging, 30000), 0u);
}

TEST(TcSoftBodyProperty, WithVertexRestPlacementRandomOperationsKeepEveryInvariant) {
  // Every block rests on its first leaf (LodTree::rest()), off its centroid: each coarse node arrives by its
  // children's fit, and fans and hanging interfaces are slanted at rest.
  EXPECT_EQ(random_operations_keep_every_invariant(Interfaces::kLinks, 30000, RestPlacement::kVertex), 0u);
  EXPECT_GT(random_operations_keep_every_invariant(Interfaces::kHanging, 30000, RestPlacement::kVertex), 0u);
}

TEST(TcSoftBodyProperty, WithMassesThatFollowTheCutRandomOperationsKeepEveryInvariant) {
  // validate() checks every node's mass against what the old and the committed cut give it (tc_cut_masses.cpp).
  EXPECT_EQ(random_operations_keep_every_invariant(Interfaces::kLinks, 30000, RestPlacement::kVertex, Masses::kCut),
            0u);
  EXPECT_GT(random_operations_keep_every_invariant(Interfaces::kHanging, 30000, RestPlacement::kVertex, Masses::kCut),
            0u);
}

TEST(TcSoftBodyProperty, WithExactOrderRandomOperationsKeepEveryInvariant) {
  // restore_order() at every boundary that displaced anything (TcSettings::exact_order), with operations in flight.
  EXPECT_GT(random_operations_keep_every_invariant(Interfaces::kHanging, 30000, RestPlacement::kVertex, Masses::kCut,
                                                   true),
            0u);
}

}  // namespace
}  // namespace tcsb
