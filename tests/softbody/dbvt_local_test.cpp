#include "softbody/dbvt_local.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace tcsb {
namespace {

btDbvtVolume box_at(float x, float y) { return btDbvtVolume::FromCR(btVector3(x, y, 0), 0.25f); }

/// Random local inserts and removes against a tree Bullet built; the tree stays sound throughout, and Bullet can
/// still edit and free it at the end.
TEST(DbvtLocal, RandomInsertsAndRemovesKeepTheTreeSound) {
  btDbvt tree;
  DbvtNodeCache nodes;
  std::vector<btDbvtNode*> leaves;
  for (int i = 0; i < 64; ++i)
    leaves.push_back(tree.insert(box_at(static_cast<float>(i % 8), static_cast<float>(i / 8)), nullptr));
  std::mt19937 rng(7);
  for (int round = 0; round < 5000; ++round) {
    std::uniform_int_distribution<std::size_t> pick(0, leaves.size() - 1);
    const std::size_t k = pick(rng);
    if (rng() % 2 == 0 || leaves.size() < 4) {
      const btVector3 c = leaves[k]->volume.Center() + btVector3(0.1f, -0.1f, 0);
      leaves.push_back(insert_leaf_beside(tree, nodes, leaves[k], btDbvtVolume::FromCR(c, 0.25f), nullptr));
    } else {
      remove_leaf_lazily(tree, nodes, leaves[k]);
      leaves[k] = leaves.back();
      leaves.pop_back();
    }
    ASSERT_STREQ(check_dbvt(tree), "") << "after round " << round;
    ASSERT_EQ(tree.m_leaves, static_cast<int>(leaves.size()));
  }
  // Bullet's own edits on nodes that came from the cache.
  btDbvtVolume far_away = box_at(100, 100);
  tree.update(leaves.front(), far_away);
  tree.optimizeIncremental(4);
  EXPECT_STREQ(check_dbvt(tree), "");
}

TEST(DbvtLocal, RemovedNodesAreReusedByTheNextInsert) {
  btDbvt tree;
  DbvtNodeCache nodes;
  btDbvtNode* a = tree.insert(box_at(0, 0), nullptr);
  btDbvtNode* b = insert_leaf_beside(tree, nodes, a, box_at(1, 0), nullptr);
  EXPECT_EQ(nodes.spare(), 0u);
  remove_leaf_lazily(tree, nodes, b);  // the leaf and the pair node above it
  EXPECT_EQ(nodes.spare(), 2u);
  btDbvtNode* c = insert_leaf_beside(tree, nodes, a, box_at(2, 0), nullptr);
  EXPECT_EQ(nodes.spare(), 0u);
  EXPECT_TRUE(c->isleaf());
  EXPECT_EQ(c->parent->childs[0], a);
  EXPECT_EQ(c->parent->childs[1], c);
  EXPECT_TRUE(c->parent->volume.Contain(box_at(2, 0)));
  EXPECT_STREQ(check_dbvt(tree), "");
}

TEST(DbvtLocal, CacheKeepsAtMostItsLimit) {
  btDbvt tree;
  DbvtNodeCache nodes;
  btDbvtNode* root = tree.insert(box_at(0, 0), nullptr);
  std::vector<btDbvtNode*> added;
  const std::size_t n = DbvtNodeCache::kMaxSpare;  // removing n leaves gives back 2n nodes
  for (std::size_t i = 0; i < n; ++i) added.push_back(insert_leaf_beside(tree, nodes, root, box_at(1, 1), nullptr));
  for (btDbvtNode* leaf : added) remove_leaf_lazily(tree, nodes, leaf);
  EXPECT_EQ(nodes.spare(), DbvtNodeCache::kMaxSpare);
  EXPECT_EQ(tree.m_leaves, 1);
  EXPECT_STREQ(check_dbvt(tree), "");
}

}  // namespace
}  // namespace tcsb
