// for_each_cut_neighbour: neighbours on the finest cut, on hand-made mixed balanced cuts, and unbalanced cuts.
#include "net/cut_adjacency.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "net/net.h"

namespace tcsb {
namespace {

std::unique_ptr<Net> make_net(int w, int h) {
  NetSpec spec;
  spec.width = w;
  spec.height = h;
  return std::make_unique<Net>(spec);
}

/// A cut as a membership vector over the tree.
struct Cut {
  explicit Cut(const LodTree& t) : tree(&t), in(t.size(), 0) {}
  /// All leaves.
  static Cut finest(const LodTree& tree) {
    Cut c(tree);
    for (std::size_t i = 0; i < tree.leaf_count(); ++i) c.in[i] = 1;
    return c;
  }
  /// Replaces the cut nodes inside `id`'s block by `id`.
  void coarsen_to(TreeId id) {
    const LodNode& n = tree->node(id);
    for (std::size_t i = 0; i < tree->size(); ++i) {
      const LodNode& m = tree->node(static_cast<TreeId>(i));
      if (m.level < n.level && m.leaf_x0 >= n.leaf_x0 && m.leaf_x1 <= n.leaf_x1 && m.leaf_y0 >= n.leaf_y0 &&
          m.leaf_y1 <= n.leaf_y1)
        in[i] = 0;
    }
    in[static_cast<std::size_t>(id)] = 1;
  }
  /// Replaces cut node `id` by its children.
  void refine(TreeId id) {
    const LodNode& n = tree->node(id);
    in[static_cast<std::size_t>(id)] = 0;
    for (int k = 0; k < n.child_count; ++k) in[static_cast<std::size_t>(n.children[static_cast<std::size_t>(k)])] = 1;
  }
  bool operator()(TreeId id) const { return in[static_cast<std::size_t>(id)] != 0; }
  std::vector<TreeId> members() const {
    std::vector<TreeId> out;
    for (std::size_t i = 0; i < in.size(); ++i)
      if (in[i]) out.push_back(static_cast<TreeId>(i));
    return out;
  }
  /// Every leaf covered exactly once (a sanity check of the test's own cut).
  bool covers_each_leaf_once() const {
    std::vector<int> cover(tree->leaf_count(), 0);
    for (TreeId id : members()) {
      const LodNode& n = tree->node(id);
      for (int y = n.leaf_y0; y < n.leaf_y1; ++y)
        for (int x = n.leaf_x0; x < n.leaf_x1; ++x) ++cover[static_cast<std::size_t>(y * tree->level_width(0) + x)];
    }
    return std::all_of(cover.begin(), cover.end(), [](int c) { return c == 1; });
  }

  const LodTree* tree;  // a pointer, so cuts can be assigned
  std::vector<char> in;
};

struct Neighbours {
  bool balanced = false;
  std::vector<TreeId> ids;  // in visit order, duplicates kept
  std::set<TreeId> set() const { return {ids.begin(), ids.end()}; }
};

Neighbours neighbours(const LodTree& tree, TreeId x, const Cut& cut) {
  Neighbours out;
  out.balanced = for_each_cut_neighbour(tree, x, cut, [&](TreeId n) { out.ids.push_back(n); });
  return out;
}

/// Brute force: cut nodes whose leaf block shares an edge segment (not just a corner) with x's block.
std::set<TreeId> touching(const LodTree& tree, TreeId x, const Cut& cut) {
  const LodNode& a = tree.node(x);
  std::set<TreeId> out;
  for (TreeId id : cut.members()) {
    if (id == x) continue;
    const LodNode& b = tree.node(id);
    const bool x_overlap = std::max(a.leaf_x0, b.leaf_x0) < std::min(a.leaf_x1, b.leaf_x1);
    const bool y_overlap = std::max(a.leaf_y0, b.leaf_y0) < std::min(a.leaf_y1, b.leaf_y1);
    const bool x_touch = a.leaf_x1 == b.leaf_x0 || b.leaf_x1 == a.leaf_x0;
    const bool y_touch = a.leaf_y1 == b.leaf_y0 || b.leaf_y1 == a.leaf_y0;
    if ((x_touch && y_overlap) || (y_touch && x_overlap)) out.insert(id);
  }
  return out;
}

/// Symmetric, duplicate-free, balanced, and equal to the brute-force relation, for every member of the cut.
void expect_consistent(const LodTree& tree, const Cut& cut) {
  ASSERT_TRUE(cut.covers_each_leaf_once());
  for (TreeId x : cut.members()) {
    const Neighbours n = neighbours(tree, x, cut);
    EXPECT_TRUE(n.balanced) << "node " << x;
    EXPECT_EQ(n.ids.size(), n.set().size()) << "node " << x << " visits a neighbour twice";
    EXPECT_EQ(n.set(), touching(tree, x, cut)) << "node " << x;
    for (TreeId y : n.ids) {
      EXPECT_TRUE(cut(y)) << "visited " << y << ", not in the cut";
      EXPECT_EQ(neighbours(tree, y, cut).set().count(x), 1u) << x << " sees " << y << " but not back";
    }
  }
}

TEST(CutAdjacency, FinestCutHasFourThreeOrTwoNeighbours) {
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{2, 2}, {3, 7}, {5, 5}, {17, 9}, {16, 16}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    const auto net = make_net(w, h);
    const LodTree& tree = net->lod();
    const Cut cut = Cut::finest(tree);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const TreeId id = net->index(x, y);
        const Neighbours n = neighbours(tree, id, cut);
        EXPECT_TRUE(n.balanced);
        const int border_sides = (x == 0) + (x == w - 1) + (y == 0) + (y == h - 1);
        EXPECT_EQ(static_cast<int>(n.ids.size()), 4 - border_sides) << "(" << x << "," << y << ")";
        std::set<TreeId> expected;
        if (x > 0) expected.insert(net->index(x - 1, y));
        if (x + 1 < w) expected.insert(net->index(x + 1, y));
        if (y > 0) expected.insert(net->index(x, y - 1));
        if (y + 1 < h) expected.insert(net->index(x, y + 1));
        EXPECT_EQ(n.set(), expected) << "(" << x << "," << y << ")";
      }
    }
    expect_consistent(tree, cut);
  }
}

TEST(CutAdjacency, FinestCutCountsOnASquare) {
  const auto net = make_net(17, 17);
  const LodTree& tree = net->lod();
  const Cut cut = Cut::finest(tree);
  int by_count[5] = {0, 0, 0, 0, 0};
  for (TreeId id : cut.members()) {
    const std::size_t count = neighbours(tree, id, cut).ids.size();
    ASSERT_LE(count, 4u);
    ++by_count[count];
  }
  EXPECT_EQ(by_count[2], 4);        // corners
  EXPECT_EQ(by_count[3], 4 * 15);   // edges
  EXPECT_EQ(by_count[4], 15 * 15);  // interior
  EXPECT_EQ(by_count[0] + by_count[1], 0);
}

TEST(CutAdjacency, CoarseBlockSeesItsEightLeafNeighboursAndTheySeeIt) {
  const auto net = make_net(17, 17);
  const LodTree& tree = net->lod();
  Cut cut = Cut::finest(tree);
  const TreeId coarse = tree.at(1, 3, 3);  // leaves 6..7 x 6..7
  cut.coarsen_to(coarse);
  ASSERT_EQ(cut.members().size(), 17u * 17 - 3);
  const Neighbours n = neighbours(tree, coarse, cut);
  EXPECT_TRUE(n.balanced);
  const std::set<TreeId> expected = {net->index(5, 6), net->index(5, 7), net->index(8, 6), net->index(8, 7),
                                     net->index(6, 5), net->index(7, 5), net->index(6, 8), net->index(7, 8)};
  EXPECT_EQ(n.ids.size(), 8u);
  EXPECT_EQ(n.set(), expected);
  for (TreeId leaf : expected) {
    const Neighbours back = neighbours(tree, leaf, cut);
    EXPECT_TRUE(back.balanced) << "leaf " << leaf;
    EXPECT_EQ(back.set().count(coarse), 1u) << "leaf " << leaf << " does not see the coarse node";
    EXPECT_EQ(back.ids.size(), 4u) << "leaf " << leaf;  // still 4 sides, one of them the coarse node
  }
  // A leaf diagonal to the block touches it at a corner only.
  EXPECT_EQ(neighbours(tree, net->index(5, 5), cut).set().count(coarse), 0u);
  expect_consistent(tree, cut);
}

TEST(CutAdjacency, PartialBorderBlockSeesItsLeafNeighbours) {
  // 17 = 16 + 1: the level-1 block (8, 3) holds the leaves (16, 6) and (16, 7) only.
  const auto net = make_net(17, 17);
  const LodTree& tree = net->lod();
  Cut cut = Cut::finest(tree);
  const TreeId coarse = tree.at(1, 8, 3);
  ASSERT_EQ(tree.node(coarse).child_count, 2);
  cut.coarsen_to(coarse);
  const Neighbours n = neighbours(tree, coarse, cut);
  EXPECT_TRUE(n.balanced);
  EXPECT_EQ(n.set(), (std::set<TreeId>{net->index(15, 6), net->index(15, 7), net->index(16, 5), net->index(16, 8)}));
  expect_consistent(tree, cut);
}

TEST(CutAdjacency, NodeOutsideTheCutSeesWhatItsBlockTouches) {
  // can_coarsen asks about a parent before it joins the cut: on the finest cut it must see the 8 leaves around
  // its block, not its own children.
  const auto net = make_net(17, 17);
  const LodTree& tree = net->lod();
  const Cut cut = Cut::finest(tree);
  const TreeId parent = tree.at(1, 3, 3);
  const Neighbours n = neighbours(tree, parent, cut);
  EXPECT_TRUE(n.balanced);
  EXPECT_EQ(n.ids.size(), 8u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(n.set().count(tree.node(parent).children[static_cast<std::size_t>(k)]), 0u);
  EXPECT_EQ(n.set(), touching(tree, parent, cut));
}

TEST(CutAdjacency, MixedCutAcrossLevelsOneAndTwo) {
  // All of a 17x17 net at level 1 but one level-2 block: the level-2 node has 8 level-1 neighbours.
  const auto net = make_net(17, 17);
  const LodTree& tree = net->lod();
  Cut cut(tree);
  for (int gy = 0; gy < tree.level_height(1); ++gy)
    for (int gx = 0; gx < tree.level_width(1); ++gx) cut.in[static_cast<std::size_t>(tree.at(1, gx, gy))] = 1;
  const TreeId big = tree.at(2, 1, 1);
  cut.coarsen_to(big);
  const Neighbours n = neighbours(tree, big, cut);
  EXPECT_TRUE(n.balanced);
  EXPECT_EQ(n.ids.size(), 8u);
  for (TreeId id : n.ids) EXPECT_EQ(tree.node(id).level, 1);
  expect_consistent(tree, cut);
}

TEST(CutAdjacency, RandomBalancedCutsAreConsistent) {
  // Coarsen random blocks whenever the result stays balanced (checked by brute force: touching blocks at most one
  // level apart), then compare the walk with brute force everywhere.
  const auto net = make_net(33, 17);
  const LodTree& tree = net->lod();
  Cut cut = Cut::finest(tree);
  unsigned state = 12345;
  int coarsened = 0;
  for (int attempt = 0; attempt < 400; ++attempt) {
    state = state * 1103515245u + 12345u;
    const TreeId id = static_cast<TreeId>(tree.leaf_count() + (state >> 8) % (tree.size() - tree.leaf_count()));
    const LodNode& n = tree.node(id);
    if (cut(id)) continue;
    bool children_in = true;
    for (int k = 0; k < n.child_count; ++k) children_in &= cut(n.children[static_cast<std::size_t>(k)]);
    if (!children_in) continue;
    Cut trial = cut;
    trial.coarsen_to(id);
    bool ok = true;
    for (TreeId t : touching(tree, id, trial)) ok &= std::abs(tree.node(t).level - n.level) <= 1;
    if (!ok) continue;
    cut = trial;
    ++coarsened;
  }
  ASSERT_GT(coarsened, 20);
  expect_consistent(tree, cut);
}

TEST(CutAdjacency, LevelTwoBesideLeavesIsUnbalanced) {
  const auto net = make_net(17, 17);
  const LodTree& tree = net->lod();
  Cut cut = Cut::finest(tree);
  const TreeId big = tree.at(2, 1, 1);  // leaves 4..7 x 4..7
  cut.coarsen_to(big);
  ASSERT_TRUE(cut.covers_each_leaf_once());
  EXPECT_FALSE(neighbours(tree, big, cut).balanced);
  // So does a leaf beside it, seen from the other side.
  EXPECT_FALSE(neighbours(tree, net->index(3, 5), cut).balanced);
  EXPECT_FALSE(neighbours(tree, net->index(5, 8), cut).balanced);
  // A leaf far from it is unaffected.
  EXPECT_TRUE(neighbours(tree, net->index(12, 12), cut).balanced);
  // Checking a level-2 candidate over the finest cut (can_coarsen of a node whose children are leaves' parents) is
  // unbalanced too: its block's neighbours would be two levels down.
  EXPECT_FALSE(neighbours(tree, tree.at(2, 2, 2), Cut::finest(tree)).balanced);
}

TEST(CutAdjacency, HalfFinerSideIsUnbalanced) {
  // A level-2 node whose right-hand neighbour block is half level 1, half leaves: the leaves are two levels below.
  const auto net = make_net(17, 17);
  const LodTree& tree = net->lod();
  Cut cut(tree);
  for (int gy = 0; gy < tree.level_height(1); ++gy)
    for (int gx = 0; gx < tree.level_width(1); ++gx) cut.in[static_cast<std::size_t>(tree.at(1, gx, gy))] = 1;
  const TreeId big = tree.at(2, 1, 1);  // level-1 (2..3, 2..3)
  cut.coarsen_to(big);
  ASSERT_TRUE(neighbours(tree, big, cut).balanced);
  cut.refine(tree.at(1, 4, 2));  // the upper of the two level-1 blocks facing its right side
  ASSERT_TRUE(cut.covers_each_leaf_once());
  const Neighbours n = neighbours(tree, big, cut);
  EXPECT_FALSE(n.balanced);
  EXPECT_EQ(n.set().count(tree.at(1, 4, 3)), 1u) << "the level-1 half is still visited";
  // The same with the lower block refined instead.
  Cut other(tree);
  for (int gy = 0; gy < tree.level_height(1); ++gy)
    for (int gx = 0; gx < tree.level_width(1); ++gx) other.in[static_cast<std::size_t>(tree.at(1, gx, gy))] = 1;
  other.coarsen_to(big);
  other.refine(tree.at(1, 4, 3));
  EXPECT_FALSE(neighbours(tree, big, other).balanced);
}

TEST(CutAdjacency, NodeInsideACutBlockNeverSeesItsOwnAncestor) {
  // Leaf (6, 6) lies inside the coarse block (1, 3, 3): the block is its parent, not its neighbour. Its sides facing
  // its siblings find nothing within one level (they are off the cut), so the walk reports them, but it must not
  // visit the block that contains it.
  const auto net = make_net(17, 17);
  const LodTree& tree = net->lod();
  Cut cut = Cut::finest(tree);
  const TreeId coarse = tree.at(1, 3, 3);
  cut.coarsen_to(coarse);
  for (const TreeId inside : {net->index(6, 6), net->index(7, 6), net->index(6, 7), net->index(7, 7)}) {
    const Neighbours n = neighbours(tree, inside, cut);
    EXPECT_EQ(n.set().count(coarse), 0u) << "leaf " << inside << " visits its own parent";
    EXPECT_FALSE(n.balanced) << "leaf " << inside;
    EXPECT_EQ(n.ids.size(), 2u) << "leaf " << inside << ": only the two outside leaves";
  }
}

TEST(CutAdjacency, MissingSideIsUnbalanced) {
  // A cut with a hole (a leaf missing, nothing covering it) leaves its neighbours with an empty side.
  const auto net = make_net(9, 9);
  const LodTree& tree = net->lod();
  Cut cut = Cut::finest(tree);
  cut.in[static_cast<std::size_t>(net->index(4, 4))] = 0;
  EXPECT_FALSE(neighbours(tree, net->index(3, 4), cut).balanced);
  EXPECT_FALSE(neighbours(tree, net->index(4, 5), cut).balanced);
  EXPECT_TRUE(neighbours(tree, net->index(1, 1), cut).balanced);
}

/// Whether a block is whole: it covers 2^level x 2^level leaves (partial blocks lie at the far borders).
bool whole(const LodNode& n) {
  const int side = 1 << n.level;
  return n.leaf_x1 - n.leaf_x0 == side && n.leaf_y1 - n.leaf_y0 == side;
}

TEST(NeighbourhoodInsideNet, IsTheBlockAndItsEightNeighboursOfItsLevelAllWhole) {
  for (const auto& [w, h] : {std::pair{9, 9}, std::pair{16, 16}, std::pair{33, 17}, std::pair{45, 45}}) {
    const auto net = make_net(w, h);
    const LodTree& tree = net->lod();
    for (TreeId id = 0; id < static_cast<TreeId>(tree.size()); ++id) {
      const LodNode& n = tree.node(id);
      bool expected = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const TreeId m = tree.at(n.level, n.gx + dx, n.gy + dy);
          expected = expected && m != kNoTreeNode && whole(tree.node(m));
        }
      EXPECT_EQ(neighbourhood_inside_net(tree, id), expected) << w << "x" << h << " node " << id;
    }
  }
}

TEST(NeighbourhoodInsideNet, OnANineByNineNet) {
  const auto net = make_net(9, 9);
  const LodTree& tree = net->lod();
  EXPECT_FALSE(neighbourhood_inside_net(tree, tree.at(0, 0, 4)));  // on the border
  EXPECT_TRUE(neighbourhood_inside_net(tree, tree.at(0, 1, 4)));
  EXPECT_TRUE(neighbourhood_inside_net(tree, tree.at(0, 7, 7)));
  EXPECT_FALSE(neighbourhood_inside_net(tree, tree.at(1, 0, 1)));  // leaves 0-1: nothing to the left
  EXPECT_TRUE(neighbourhood_inside_net(tree, tree.at(1, 1, 1)));   // leaves 2-3, neighbours 0-1 and 4-5
  EXPECT_TRUE(neighbourhood_inside_net(tree, tree.at(1, 2, 2)));   // leaves 4-5, neighbours 2-3 and 6-7
  EXPECT_FALSE(neighbourhood_inside_net(tree, tree.at(1, 3, 2)));  // its right neighbour is leaf 8 alone
  EXPECT_FALSE(neighbourhood_inside_net(tree, tree.at(2, 1, 1)));  // leaves 4-7: the block to its right is partial
  EXPECT_FALSE(neighbourhood_inside_net(tree, tree.root()));
}

}  // namespace
}  // namespace tcsb
