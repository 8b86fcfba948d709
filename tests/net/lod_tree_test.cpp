// LodTree: structural invariants, checked by brute force against the leaves, over square, non-square, thin and
// power-of-two-plus-one grids, with every pin pattern that matters.
#include "net/lod_tree.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "net/net.h"

namespace tcsb {
namespace {

struct TreeSize {
  int w, h;
};
const std::vector<TreeSize> kTreeSizes = {{2, 2}, {3, 3},  {2, 9},   {9, 2},   {4, 8},  {16, 16},
                                          {5, 7}, {17, 9}, {33, 17}, {65, 65}, {64, 32}};

std::unique_ptr<Net> tree_net(int w, int h, unsigned pins = kAllCorners, MassMode mode = MassMode::kTotal,
                              RestPlacement rest = RestPlacement::kCentroid) {
  NetSpec spec;
  spec.width = w;
  spec.height = h;
  spec.pinned_corners = pins;
  spec.mass_mode = mode;
  spec.size_x = 7.0;
  spec.size_z = 3.0;
  return std::make_unique<Net>(spec, rest);
}

std::string label(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

/// Runs `check(tree, net)` over every size, with all corners pinned and with one corner pinned.
template <class Check>
void for_each_tree(Check&& check) {
  for (const TreeSize s : kTreeSizes)
    for (const unsigned pins : {unsigned(kAllCorners), unsigned(kCornerMaxMin), 0u}) {
      SCOPED_TRACE(label(s.w, s.h) + " pins " + std::to_string(pins));
      const auto net = tree_net(s.w, s.h, pins);
      check(net->lod(), *net);
    }
}

TEST(LodTree, LevelSizesCeilHalveDownToOneNode) {
  for_each_tree([](const LodTree& tree, const Net& net) {
    ASSERT_GE(tree.level_count(), 1);
    EXPECT_EQ(tree.level_width(0), net.width());
    EXPECT_EQ(tree.level_height(0), net.height());
    std::size_t total = 0;
    for (int l = 0; l < tree.level_count(); ++l) {
      total += static_cast<std::size_t>(tree.level_width(l)) * tree.level_height(l);
      if (l > 0) {
        EXPECT_EQ(tree.level_width(l), (tree.level_width(l - 1) + 1) / 2) << "level " << l;
        EXPECT_EQ(tree.level_height(l), (tree.level_height(l - 1) + 1) / 2) << "level " << l;
        EXPECT_FALSE(tree.level_width(l - 1) == 1 && tree.level_height(l - 1) == 1) << "a level after the root";
      }
    }
    const int last = tree.level_count() - 1;
    EXPECT_EQ(tree.level_width(last), 1);
    EXPECT_EQ(tree.level_height(last), 1);
    EXPECT_EQ(tree.size(), total);
    EXPECT_EQ(tree.nodes().size(), total);
    EXPECT_EQ(tree.leaf_count(), net.node_count());
    EXPECT_EQ(tree.root(), static_cast<TreeId>(total - 1));
  });
}

TEST(LodTree, KnownLevelCounts) {
  EXPECT_EQ(tree_net(2, 2)->lod().level_count(), 2);
  EXPECT_EQ(tree_net(65, 65)->lod().level_count(), 8);  // 65 33 17 9 5 3 2 1
  EXPECT_EQ(tree_net(64, 64)->lod().level_count(), 7);  // 64 32 16 8 4 2 1
  EXPECT_EQ(tree_net(2, 9)->lod().level_count(), 5);    // 9 5 3 2 1
  EXPECT_EQ(tree_net(65, 65)->lod().size(), 65u * 65 + 33 * 33 + 17 * 17 + 9 * 9 + 5 * 5 + 3 * 3 + 2 * 2 + 1);
}

TEST(LodTree, AtMatchesNodeCoordinatesAndOrdering) {
  for_each_tree([](const LodTree& tree, const Net&) {
    TreeId expected = 0;
    for (int l = 0; l < tree.level_count(); ++l)
      for (int gy = 0; gy < tree.level_height(l); ++gy)
        for (int gx = 0; gx < tree.level_width(l); ++gx, ++expected) {
          const TreeId id = tree.at(l, gx, gy);
          ASSERT_EQ(id, expected) << "level " << l << " (" << gx << "," << gy << ")";
          const LodNode& n = tree.node(id);
          ASSERT_EQ(n.level, l);
          ASSERT_EQ(n.gx, gx);
          ASSERT_EQ(n.gy, gy);
          ASSERT_EQ(n.is_leaf(), l == 0);
        }
  });
}

// The cut masses' climbs start from leaf_at, which skips at()'s checks: it must name the same leaf everywhere on the
// grid, of non-square and thin trees too.
TEST(LodTree, LeafAtIsAtOnLevelZero) {
  for_each_tree([](const LodTree& tree, const Net&) {
    for (int gy = 0; gy < tree.level_height(0); ++gy)
      for (int gx = 0; gx < tree.level_width(0); ++gx) ASSERT_EQ(tree.leaf_at(gx, gy), tree.at(0, gx, gy));
  });
}

// Cut adjacency finds a node's parent by grid arithmetic (at half its coordinates, one level up) rather than by
// reading the node; the two must agree for every node, the root included.
TEST(LodTree, ParentIsTheNodeAtHalfTheCoordinatesOneLevelUp) {
  for_each_tree([](const LodTree& tree, const Net&) {
    for (const LodNode& n : tree.nodes()) ASSERT_EQ(tree.at(n.level + 1, n.gx >> 1, n.gy >> 1), n.parent);
  });
}

TEST(LodTree, AtOutOfRangeIsNoTreeNode) {
  for_each_tree([](const LodTree& tree, const Net&) {
    const int top = tree.level_count();
    EXPECT_EQ(tree.at(-1, 0, 0), kNoTreeNode);
    EXPECT_EQ(tree.at(top, 0, 0), kNoTreeNode);
    EXPECT_EQ(tree.at(top - 1, 0, 0), tree.root());
    for (int l = 0; l < top; ++l) {
      EXPECT_EQ(tree.at(l, -1, 0), kNoTreeNode);
      EXPECT_EQ(tree.at(l, 0, -1), kNoTreeNode);
      EXPECT_EQ(tree.at(l, tree.level_width(l), 0), kNoTreeNode);
      EXPECT_EQ(tree.at(l, 0, tree.level_height(l)), kNoTreeNode);
      EXPECT_EQ(tree.at(l, tree.level_width(l), tree.level_height(l)), kNoTreeNode);
      EXPECT_NE(tree.at(l, tree.level_width(l) - 1, tree.level_height(l) - 1), kNoTreeNode);
    }
  });
}

TEST(LodTree, EveryLeafLiesOnExactlyOnePathToTheRoot) {
  for_each_tree([](const LodTree& tree, const Net&) {
    // Each non-root node is listed as a child exactly once, by its parent; the root by nobody.
    std::vector<int> listed(tree.size(), 0);
    for (std::size_t id = 0; id < tree.size(); ++id) {
      const LodNode& n = tree.node(static_cast<TreeId>(id));
      for (int k = 0; k < n.child_count; ++k) {
        const TreeId c = n.children[static_cast<std::size_t>(k)];
        ASSERT_GE(c, 0);
        ASSERT_LT(static_cast<std::size_t>(c), tree.size());
        ++listed[static_cast<std::size_t>(c)];
        EXPECT_EQ(tree.node(c).parent, static_cast<TreeId>(id));
      }
      for (int k = n.child_count; k < 4; ++k) EXPECT_EQ(n.children[static_cast<std::size_t>(k)], kNoTreeNode);
    }
    for (std::size_t id = 0; id + 1 < tree.size(); ++id) ASSERT_EQ(listed[id], 1) << "node " << id;
    EXPECT_EQ(listed.back(), 0);
    EXPECT_EQ(tree.node(tree.root()).parent, kNoTreeNode);
    // Walking up from any leaf climbs one level at a time, through nodes whose block holds the leaf, to the root.
    for (std::size_t leaf = 0; leaf < tree.leaf_count(); ++leaf) {
      const int lx = static_cast<int>(leaf) % tree.level_width(0), ly = static_cast<int>(leaf) / tree.level_width(0);
      TreeId at = static_cast<TreeId>(leaf);
      int steps = 0;
      while (tree.node(at).parent != kNoTreeNode) {
        const TreeId up = tree.node(at).parent;
        ASSERT_EQ(tree.node(up).level, tree.node(at).level + 1);
        const LodNode& u = tree.node(up);
        ASSERT_TRUE(lx >= u.leaf_x0 && lx < u.leaf_x1 && ly >= u.leaf_y0 && ly < u.leaf_y1);
        at = up;
        ASSERT_LT(++steps, tree.level_count()) << "cycle above leaf " << leaf;
      }
      ASSERT_EQ(at, tree.root()) << "leaf " << leaf;
      ASSERT_EQ(steps, tree.level_count() - 1);
    }
  });
}

TEST(LodTree, LeafBlocksFollowTheLevelGrid) {
  for_each_tree([](const LodTree& tree, const Net& net) {
    for (const LodNode& n : tree.nodes()) {
      const int span = 1 << n.level;
      ASSERT_EQ(n.leaf_x0, n.gx * span);
      ASSERT_EQ(n.leaf_y0, n.gy * span);
      ASSERT_EQ(n.leaf_x1, std::min((n.gx + 1) * span, net.width()));
      ASSERT_EQ(n.leaf_y1, std::min((n.gy + 1) * span, net.height()));
    }
    const LodNode& root = tree.node(tree.root());
    EXPECT_EQ(root.leaf_x0, 0);
    EXPECT_EQ(root.leaf_y0, 0);
    EXPECT_EQ(root.leaf_x1, net.width());
    EXPECT_EQ(root.leaf_y1, net.height());
  });
}

TEST(LodTree, SpatialRanksOrderEveryBlockCentreRowMajor) {
  for_each_tree([](const LodTree& tree, const Net&) {
    std::vector<TreeId> by_rank(tree.size(), kNoTreeNode);
    for (std::size_t id = 0; id < tree.size(); ++id) {
      const std::int32_t r = tree.spatial_rank(static_cast<TreeId>(id));
      ASSERT_GE(r, 0);
      ASSERT_LT(static_cast<std::size_t>(r), tree.size());
      ASSERT_EQ(by_rank[static_cast<std::size_t>(r)], kNoTreeNode) << "rank " << r << " given twice";
      by_rank[static_cast<std::size_t>(r)] = static_cast<TreeId>(id);
    }
    // Twice the block centre, (row, column), never decreases along the ranks; ties keep the lower id first.
    const auto centre = [&](TreeId id) {
      const LodNode& n = tree.node(id);
      return std::make_pair(n.leaf_y0 + n.leaf_y1, n.leaf_x0 + n.leaf_x1);
    };
    for (std::size_t r = 1; r < by_rank.size(); ++r) {
      ASSERT_LE(centre(by_rank[r - 1]), centre(by_rank[r])) << "rank " << r;
      if (centre(by_rank[r - 1]) == centre(by_rank[r])) {
        ASSERT_LT(by_rank[r - 1], by_rank[r]);
      }
    }
    // So the finest cut alone comes out in grid order.
    for (std::size_t leaf = 1; leaf < tree.leaf_count(); ++leaf)
      ASSERT_LT(tree.spatial_rank(static_cast<TreeId>(leaf - 1)), tree.spatial_rank(static_cast<TreeId>(leaf)));
  });
}

TEST(LodTree, ChildrenPartitionTheParentsBlock) {
  for_each_tree([](const LodTree& tree, const Net&) {
    for (const LodNode& n : tree.nodes()) {
      if (n.is_leaf()) continue;
      ASSERT_GE(n.child_count, 1);
      ASSERT_LE(n.child_count, 4);
      const int bw = n.leaf_x1 - n.leaf_x0, bh = n.leaf_y1 - n.leaf_y0;
      std::vector<int> covered(static_cast<std::size_t>(bw * bh), 0);
      for (int k = 0; k < n.child_count; ++k) {
        const LodNode& c = tree.node(n.children[static_cast<std::size_t>(k)]);
        ASSERT_EQ(c.level, n.level - 1);
        ASSERT_TRUE(c.gx / 2 == n.gx && c.gy / 2 == n.gy);
        for (int y = c.leaf_y0; y < c.leaf_y1; ++y)
          for (int x = c.leaf_x0; x < c.leaf_x1; ++x) {
            ASSERT_TRUE(x >= n.leaf_x0 && x < n.leaf_x1 && y >= n.leaf_y0 && y < n.leaf_y1)
                << "child block leaks out of its parent";
            ++covered[static_cast<std::size_t>((y - n.leaf_y0) * bw + (x - n.leaf_x0))];
          }
      }
      for (int v : covered) ASSERT_EQ(v, 1) << "children overlap or leave a gap";
    }
  });
}

TEST(LodTree, FullBlocksHaveFourChildrenAndBorderBlocksFewer) {
  const auto net = tree_net(17, 9);
  const LodTree& tree = net->lod();
  EXPECT_EQ(tree.node(tree.at(1, 0, 0)).child_count, 4);
  EXPECT_EQ(tree.node(tree.at(1, 8, 0)).child_count, 2);  // leaf column 16 alone
  EXPECT_EQ(tree.node(tree.at(1, 0, 4)).child_count, 2);  // leaf row 8 alone
  EXPECT_EQ(tree.node(tree.at(1, 8, 4)).child_count, 1);  // leaf (16, 8) alone
}

TEST(LodTree, MassIsTheSumOfTheChildrenAndTheRootHoldsItAll) {
  for (const MassMode mode : {MassMode::kTotal, MassMode::kPerNode}) {
    for_each_tree([mode](const LodTree&, const Net& base) {
      const auto net = tree_net(base.width(), base.height(), base.spec().pinned_corners, mode);
      const LodTree& tree = net->lod();
      for (const LodNode& n : tree.nodes()) {
        if (n.is_leaf()) continue;
        double sum = 0;
        for (int k = 0; k < n.child_count; ++k) sum += tree.node(n.children[static_cast<std::size_t>(k)]).mass;
        ASSERT_NEAR(n.mass, sum, 1e-12 * std::max(1.0, sum));
        double leaves = 0;
        for (int y = n.leaf_y0; y < n.leaf_y1; ++y)
          for (int x = n.leaf_x0; x < n.leaf_x1; ++x)
            leaves += net->masses()[static_cast<std::size_t>(net->index(x, y))];
        ASSERT_NEAR(n.mass, leaves, 1e-12 * std::max(1.0, leaves));
      }
      for (std::size_t i = 0; i < tree.leaf_count(); ++i) ASSERT_EQ(tree.nodes()[i].mass, net->masses()[i]);
      EXPECT_NEAR(tree.node(tree.root()).mass, net->total_mass(), 1e-9 * net->total_mass());
      EXPECT_NEAR(tree.node(tree.root()).mass, mode == MassMode::kTotal ? 1.0 : 1.0 * net->node_count(), 1e-9);
    });
  }
}

TEST(LodTree, CentroidIsTheMassWeightedMeanOfTheBlocksLeaves) {
  for_each_tree([](const LodTree& tree, const Net& net) {
    for (std::size_t id = 0; id < tree.size(); ++id) {
      const LodNode& n = tree.node(static_cast<TreeId>(id));
      Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
      double mass = 0;
      for (int y = n.leaf_y0; y < n.leaf_y1; ++y)
        for (int x = n.leaf_x0; x < n.leaf_x1; ++x) {
          const std::size_t i = static_cast<std::size_t>(net.index(x, y));
          weighted += net.masses()[i] * net.rest_positions()[i];
          mass += net.masses()[i];
        }
      const Eigen::Vector3d expected = weighted / mass;
      ASSERT_LT((tree.centroid(static_cast<TreeId>(id)) - expected).norm(), 1e-9)
          << "level " << n.level << " (" << n.gx << "," << n.gy << ")";
    }
  });
}

TEST(LodTree, CentroidOfUniformBlockIsItsMidpoint) {
  // Uniform masses: the centroid of a block is the midpoint of its corner leaves. Independent of the weighting code.
  const auto net = tree_net(33, 17);
  const LodTree& tree = net->lod();
  for (std::size_t id = 0; id < tree.size(); ++id) {
    const LodNode& n = tree.node(static_cast<TreeId>(id));
    const Eigen::Vector3d& a = net->rest_positions()[static_cast<std::size_t>(net->index(n.leaf_x0, n.leaf_y0))];
    const Eigen::Vector3d& b =
        net->rest_positions()[static_cast<std::size_t>(net->index(n.leaf_x1 - 1, n.leaf_y1 - 1))];
    ASSERT_LT((tree.centroid(static_cast<TreeId>(id)) - 0.5 * (a + b)).norm(), 1e-9);
  }
  EXPECT_LT(tree.centroid(tree.root()).head<1>().norm(), 1e-12);
}

TEST(LodTree, PinnedLeafCountAnchorAndRestFollowTheBlock) {
  for_each_tree([](const LodTree& tree, const Net& net) {
    for (std::size_t id = 0; id < tree.size(); ++id) {
      const LodNode& n = tree.node(static_cast<TreeId>(id));
      int pinned = 0;
      TreeId only = kNoTreeNode;
      for (int y = n.leaf_y0; y < n.leaf_y1; ++y)
        for (int x = n.leaf_x0; x < n.leaf_x1; ++x)
          if (net.pinned()[static_cast<std::size_t>(net.index(x, y))]) {
            ++pinned;
            only = net.index(x, y);
          }
      ASSERT_EQ(n.pinned_leaf_count, pinned) << "node " << id;
      ASSERT_EQ(n.pinned(), pinned > 0);
      ASSERT_EQ(n.simulable(), pinned <= 1) << "node " << id;
      if (pinned == 1) {
        ASSERT_EQ(n.anchor_leaf, only) << "node " << id;
        ASSERT_EQ(tree.rest(static_cast<TreeId>(id)), net.rest_positions()[static_cast<std::size_t>(only)])
            << "node " << id;
      } else {
        ASSERT_EQ(n.anchor_leaf, kNoTreeNode) << "node " << id;
        // Its centroid, but on the border along an axis where it touches one border.
        Eigen::Vector3d expected = tree.centroid(static_cast<TreeId>(id));
        const auto leaf = [&](int x, int y) { return net.rest_positions()[static_cast<std::size_t>(net.index(x, y))]; };
        if (n.leaf_x0 == 0 && n.leaf_x1 < net.width()) expected.x() = leaf(0, 0).x();
        if (n.leaf_x0 > 0 && n.leaf_x1 == net.width()) expected.x() = leaf(net.width() - 1, 0).x();
        if (n.leaf_y0 == 0 && n.leaf_y1 < net.height()) expected.z() = leaf(0, 0).z();
        if (n.leaf_y0 > 0 && n.leaf_y1 == net.height()) expected.z() = leaf(0, net.height() - 1).z();
        ASSERT_EQ(tree.rest(static_cast<TreeId>(id)), expected) << "node " << id;
        const bool border = n.leaf_x0 == 0 || n.leaf_y0 == 0 || n.leaf_x1 == net.width() || n.leaf_y1 == net.height();
        ASSERT_EQ(tree.touches_border(n), border) << "node " << id;
        if (!border) {
          ASSERT_EQ(tree.rest(static_cast<TreeId>(id)), tree.centroid(static_cast<TreeId>(id)));
        }
      }
    }
  });
}

TEST(LodTree, BlocksOnTheBorderRestOnIt) {
  // 10x10 (full blocks) and 9x9 (the last column and row of blocks one leaf wide), no pins.
  for (const int side : {10, 9}) {
    SCOPED_TRACE(side);
    const auto net = tree_net(side, side, 0);
    const LodTree& t = net->lod();
    const auto leaf = [&](int x, int y) { return net->rest_positions()[static_cast<std::size_t>(net->index(x, y))]; };
    for (int i = 0; i < side * side; ++i) EXPECT_EQ(t.rest(i), net->rest_positions()[static_cast<std::size_t>(i)]);
    // Level 1, first column (leaves x 0-1, z 2-3): on the x = 0 edge, halfway between its rows along z.
    const TreeId west = t.at(1, 0, 1);
    EXPECT_EQ(t.rest(west).x(), leaf(0, 2).x());
    EXPECT_EQ(t.rest(west).z(), t.centroid(west).z());
    EXPECT_NE(t.rest(west), t.centroid(west));
    // Level 1, last column: on the far edge (the centroid is there already on 9x9).
    const TreeId east = t.at(1, t.level_width(1) - 1, 1);
    EXPECT_EQ(t.rest(east).x(), leaf(side - 1, 2).x());
    EXPECT_EQ(t.rest(east).z(), t.centroid(east).z());
    // A free corner block rests on the corner; an interior block at its centroid.
    EXPECT_EQ(t.rest(t.at(1, 0, 0)).x(), leaf(0, 0).x());
    EXPECT_EQ(t.rest(t.at(1, 0, 0)).z(), leaf(0, 0).z());
    EXPECT_EQ(t.rest(t.at(2, 0, t.level_height(2) - 1)).x(), leaf(0, side - 1).x());
    EXPECT_EQ(t.rest(t.at(2, 0, t.level_height(2) - 1)).z(), leaf(0, side - 1).z());
    EXPECT_EQ(t.rest(t.at(1, 1, 1)), t.centroid(t.at(1, 1, 1)));
    // The root touches both borders along each axis: its centroid.
    EXPECT_EQ(t.rest(t.root()), t.centroid(t.root()));
  }
}

TEST(LodTree, VertexBlocksRestOnTheirFirstLeafOrOnTheLastBorder) {
  for (const TreeSize sz : kTreeSizes)
    for (const unsigned pins : {unsigned(kAllCorners), unsigned(kCornerMaxMin), 0u}) {
      SCOPED_TRACE(label(sz.w, sz.h) + " pins " + std::to_string(pins));
      const auto net = tree_net(sz.w, sz.h, pins, MassMode::kTotal, RestPlacement::kVertex);
      const LodTree& tree = net->lod();
      ASSERT_EQ(tree.placement(), RestPlacement::kVertex);
      const auto leaf = [&](int x, int y) { return net->rest_positions()[static_cast<std::size_t>(net->index(x, y))]; };
      for (std::size_t i = 0; i < tree.size(); ++i) {
        const auto id = static_cast<TreeId>(i);
        const LodNode& n = tree.node(id);
        ASSERT_TRUE(tree.may_rest_off_centroid(n));
        if (n.is_leaf()) {
          ASSERT_EQ(tree.rest(id), leaf(n.gx, n.gy)) << "leaf " << id;
          continue;
        }
        if (n.pinned_leaf_count == 1) {  // on its pinned leaf, as with centroid placement
          ASSERT_EQ(tree.rest(id), net->rest_positions()[static_cast<std::size_t>(n.anchor_leaf)]) << "node " << id;
          continue;
        }
        const bool span_x = n.leaf_x0 == 0 && n.leaf_x1 == net->width();
        const bool span_y = n.leaf_y0 == 0 && n.leaf_y1 == net->height();
        const int vx = n.leaf_x1 == net->width() ? net->width() - 1 : n.leaf_x0;
        const int vy = n.leaf_y1 == net->height() ? net->height() - 1 : n.leaf_y0;
        Eigen::Vector3d expected = tree.centroid(id);
        if (!span_x && !span_y) {
          expected = leaf(vx, vy);
        } else {
          if (!span_x) expected.x() = leaf(vx, vy).x();
          if (!span_y) expected.z() = leaf(vx, vy).z();
        }
        ASSERT_EQ(tree.rest(id), expected) << "node " << id;
      }
      // The rest placement changes where blocks rest, nothing else of the tree.
      const auto centroid_net = tree_net(sz.w, sz.h, pins);
      for (std::size_t i = 0; i < tree.size(); ++i) {
        const auto id = static_cast<TreeId>(i);
        ASSERT_EQ(tree.node(id).mass, centroid_net->lod().node(id).mass);
        ASSERT_EQ(tree.node(id).anchor_leaf, centroid_net->lod().node(id).anchor_leaf);
        ASSERT_EQ(tree.centroid(id), centroid_net->lod().centroid(id));
        ASSERT_EQ(tree.spatial_rank(id), centroid_net->lod().spatial_rank(id));
        if (tree.node(id).is_leaf()) {
          ASSERT_EQ(tree.rest(id), centroid_net->lod().rest(id));
        }
      }
    }
}

TEST(LodTree, VertexWholeLevelCutsOfPowerOfTwoPlusOneNetsAreEvenlySpacedSubGrids) {
  // A (2^k m + 1)-wide net: level l <= k rests on leaf columns and rows 0, 2^l, 2 * 2^l, ..., the last one included
  // (a partial block of one leaf), pinned corners too. Centroid placement does not: level 1 of 45 wide rests at
  // leaves 0, 2.5, 4.5, ..., 42.5, 44.
  for (const TreeSize sz : std::vector<TreeSize>{{45, 45}, {33, 17}, {81, 81}, {9, 5}})
    for (const unsigned pins : {unsigned(kAllCorners), 0u}) {
      SCOPED_TRACE(label(sz.w, sz.h) + " pins " + std::to_string(pins));
      const auto net = tree_net(sz.w, sz.h, pins, MassMode::kTotal, RestPlacement::kVertex);
      const LodTree& tree = net->lod();
      const auto leaf = [&](int x, int y) { return net->rest_positions()[static_cast<std::size_t>(net->index(x, y))]; };
      int levels = 0;
      for (int l = 1; (sz.w - 1) % (1 << l) == 0 && (sz.h - 1) % (1 << l) == 0; ++l, ++levels) {
        const int step = 1 << l;
        ASSERT_EQ(tree.level_width(l), (sz.w - 1) / step + 1);
        ASSERT_EQ(tree.level_height(l), (sz.h - 1) / step + 1);
        for (int gy = 0; gy < tree.level_height(l); ++gy)
          for (int gx = 0; gx < tree.level_width(l); ++gx)
            ASSERT_EQ(tree.rest(tree.at(l, gx, gy)), leaf(step * gx, step * gy))
                << "level " << l << " " << gx << "," << gy;
      }
      EXPECT_GE(levels, 1);
      const auto centroid_net = tree_net(sz.w, sz.h, pins);
      EXPECT_NE(centroid_net->lod().rest(centroid_net->lod().at(1, 1, 1)), leaf(2, 2));
    }
}

TEST(LodTree, BlocksHoldingTwoCornersAreNotSimulable) {
  // 2x9 with all corners: the two corners of each short side share a level-1 block at once.
  const auto net = tree_net(2, 9);
  const LodTree& tree = net->lod();
  EXPECT_EQ(tree.node(tree.at(1, 0, 0)).pinned_leaf_count, 2);
  EXPECT_FALSE(tree.node(tree.at(1, 0, 0)).simulable());
  EXPECT_EQ(tree.node(tree.at(1, 0, 4)).pinned_leaf_count, 2);
  EXPECT_EQ(tree.node(tree.at(1, 0, 1)).pinned_leaf_count, 0);
  EXPECT_TRUE(tree.node(tree.at(1, 0, 1)).simulable());
  EXPECT_EQ(tree.node(tree.root()).pinned_leaf_count, 4);
  EXPECT_FALSE(tree.node(tree.root()).simulable());
  // 65x65: the blocks of the last row and column are partial (65 = 64 + 1), so the (64, 64) corner is alone in its
  // block at every level below the root, and only the root holds two corners or more.
  const auto big = tree_net(65, 65);
  const LodTree& t = big->lod();
  for (int l = 0; l + 1 < t.level_count(); ++l) {
    const TreeId corner = t.at(l, t.level_width(l) - 1, t.level_height(l) - 1);
    EXPECT_EQ(t.node(corner).pinned_leaf_count, 1) << "level " << l;
    EXPECT_TRUE(t.node(corner).simulable()) << "level " << l;
    EXPECT_EQ(t.node(corner).anchor_leaf, big->index(64, 64)) << "level " << l;
    EXPECT_EQ(t.rest(corner), big->rest_positions()[static_cast<std::size_t>(big->index(64, 64))]);
    EXPECT_EQ(t.node(corner).leaf_x1 - t.node(corner).leaf_x0, 1) << "level " << l;
    // The (0, 0) corner's blocks are full 2^l squares: they rest on the corner, away from their centroid.
    const TreeId low_id = t.at(l, 0, 0);
    const LodNode& low = t.node(low_id);
    EXPECT_EQ(low.anchor_leaf, 0) << "level " << l;
    EXPECT_EQ(t.rest(low_id), big->rest_positions()[0]) << "level " << l;
    if (l > 0) {
      EXPECT_NE(t.rest(low_id), t.centroid(low_id)) << "level " << l;
    }
  }
  EXPECT_EQ(t.node(t.root()).pinned_leaf_count, 4);
  EXPECT_FALSE(t.node(t.root()).simulable());
  // 64x64: the level-5 (2x2) blocks each hold one corner; with a 32-leaf side, level 5's blocks are 32x32.
  const auto even = tree_net(64, 64);
  const LodTree& e = even->lod();
  EXPECT_EQ(e.node(e.at(5, 1, 0)).pinned_leaf_count, 1);
  EXPECT_EQ(e.node(e.at(5, 1, 0)).anchor_leaf, even->index(63, 0));
}

TEST(LodTree, ThinGridsDirectly) {
  // One-wide grids: not a valid Net, but a valid tree. 1x9 halves along z only.
  const int w = 1, h = 9;
  std::vector<Eigen::Vector3d> rest;
  std::vector<double> mass;
  std::vector<std::uint8_t> pinned(static_cast<std::size_t>(w * h), 0);
  for (int y = 0; y < h; ++y) {
    rest.emplace_back(0.0, 1.0, static_cast<double>(y));
    mass.push_back(1.0 + y);
  }
  pinned[0] = 1;
  const LodTree tree(w, h, rest, mass, pinned);
  ASSERT_EQ(tree.level_count(), 5);  // 9 5 3 2 1
  for (int l = 0; l < tree.level_count(); ++l) EXPECT_EQ(tree.level_width(l), 1);
  EXPECT_EQ(tree.size(), 9u + 5 + 3 + 2 + 1);
  EXPECT_DOUBLE_EQ(tree.node(tree.root()).mass, 45.0);
  EXPECT_NEAR(tree.centroid(tree.root()).z(),
              (0 * 1 + 1 * 2 + 2 * 3 + 3 * 4 + 4 * 5 + 5 * 6 + 6 * 7 + 7 * 8 + 8 * 9) / 45.0, 1e-12);
  EXPECT_EQ(tree.node(tree.root()).anchor_leaf, 0);
  EXPECT_EQ(tree.rest(tree.root()), rest[0]);
  const TreeId l1_id = tree.at(1, 0, 1);  // leaves 2 and 3
  const LodNode& l1 = tree.node(l1_id);
  EXPECT_EQ(l1.child_count, 2);
  EXPECT_DOUBLE_EQ(l1.mass, 3.0 + 4.0);
  EXPECT_NEAR(tree.centroid(l1_id).z(), (2 * 3.0 + 3 * 4.0) / 7.0, 1e-12);
  EXPECT_EQ(tree.at(0, 1, 0), kNoTreeNode);
}

TEST(LodTree, RejectsMismatchedArrays) {
  std::vector<Eigen::Vector3d> rest(6, Eigen::Vector3d::Zero());
  std::vector<double> mass(6, 1.0);
  std::vector<std::uint8_t> pinned(6, 0);
  EXPECT_NO_THROW(LodTree(2, 3, rest, mass, pinned));
  EXPECT_THROW(LodTree(3, 3, rest, mass, pinned), std::invalid_argument);
  mass.pop_back();
  EXPECT_THROW(LodTree(2, 3, rest, mass, pinned), std::invalid_argument);
  EXPECT_THROW(LodTree(0, 3, rest, mass, pinned), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
