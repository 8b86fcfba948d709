#include "softbody/dbvt_local.h"

#include <LinearMath/btAlignedAllocator.h>

#include <new>
#include <vector>

namespace tcsb {

namespace {

void free_node(btDbvtNode* node) {
  node->~btDbvtNode();
  btAlignedFree(node);
}

int index_in_parent(const btDbvtNode* node) { return node->parent->childs[1] == node ? 1 : 0; }

}  // namespace

DbvtNodeCache::~DbvtNodeCache() { release(); }

void DbvtNodeCache::release() {
  for (void* storage : spare_) btAlignedFree(storage);
  spare_.clear();
}

btDbvtNode* DbvtNodeCache::take(btDbvtNode* parent) {
  void* storage;
  if (spare_.empty()) {
    storage = btAlignedAlloc(sizeof(btDbvtNode), 16);
  } else {
    storage = spare_.back();
    spare_.pop_back();
  }
  auto* node = new (storage) btDbvtNode();
  node->parent = parent;
  node->childs[0] = nullptr;
  node->childs[1] = nullptr;
  return node;
}

void DbvtNodeCache::give(btDbvtNode* node) {
  if (spare_.size() < kMaxSpare) {
    node->~btDbvtNode();  // a spare is storage only; take() constructs a node in it again
    spare_.push_back(static_cast<void*>(node));
  } else {
    free_node(node);
  }
}

btDbvtNode* insert_leaf_beside(btDbvt& tree, DbvtNodeCache& nodes, btDbvtNode* beside, const btDbvtVolume& volume,
                               void* data, std::int32_t* ancestors) {
  btDbvtNode* leaf = nodes.take(nullptr);
  leaf->volume = volume;
  leaf->data = data;  // shares storage with childs[0]; childs[1] == nullptr marks a leaf
  btDbvtNode* prev = beside->parent;
  btDbvtNode* pair = nodes.take(prev);
  ::Merge(volume, beside->volume, pair->volume);
  pair->childs[0] = beside;
  pair->childs[1] = leaf;
  if (prev != nullptr)
    prev->childs[index_in_parent(beside)] = pair;
  else
    tree.m_root = pair;
  beside->parent = pair;
  leaf->parent = pair;
  std::int32_t visited = 0;
  for (btDbvtNode* node = pair; (prev = node->parent) != nullptr; node = prev) {
    ++visited;
    if (prev->volume.Contain(node->volume)) break;
    ::Merge(prev->childs[0]->volume, prev->childs[1]->volume, prev->volume);
  }
  ++tree.m_leaves;
  if (ancestors != nullptr) *ancestors += visited;
  return leaf;
}

void remove_leaf_lazily(btDbvt& tree, DbvtNodeCache& nodes, btDbvtNode* leaf) {
  if (leaf == tree.m_root) {
    tree.m_root = nullptr;
  } else {
    btDbvtNode* parent = leaf->parent;
    btDbvtNode* prev = parent->parent;
    btDbvtNode* sibling = parent->childs[1 - index_in_parent(leaf)];
    if (prev != nullptr) {
      prev->childs[index_in_parent(parent)] = sibling;
      sibling->parent = prev;
    } else {
      tree.m_root = sibling;
      sibling->parent = nullptr;
    }
    nodes.give(parent);
  }
  nodes.give(leaf);
  --tree.m_leaves;
}

const char* check_dbvt(const btDbvt& tree) {
  if (tree.m_root == nullptr) return tree.m_leaves == 0 ? "" : "empty tree with a leaf count";
  if (tree.m_root->parent != nullptr) return "root has a parent";
  int leaves = 0;
  std::vector<const btDbvtNode*> stack{tree.m_root};
  while (!stack.empty()) {
    const btDbvtNode* node = stack.back();
    stack.pop_back();
    if (node->isleaf()) {
      ++leaves;
      continue;
    }
    for (const btDbvtNode* child : node->childs) {
      if (child == nullptr || child->parent != node) return "broken parent link";
      if (!node->volume.Contain(child->volume)) return "a box does not contain its child's box";
      stack.push_back(child);
    }
  }
  return leaves == tree.m_leaves ? "" : "leaf count differs from the leaves in the tree";
}

}  // namespace tcsb
