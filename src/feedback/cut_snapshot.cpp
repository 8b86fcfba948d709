#include "feedback/cut_snapshot.h"

namespace tcsb {

CutView cut_view(const TcSoftBody& body) {
  return {&body.tree(), body.states(), body.bullet_indices(), body.tree_ids(), body.cut_links()};
}

FinestCut::FinestCut(const Net& net)
    : tree_(&net.lod()), state_(tree_->size(), CutState::kOff), index_(tree_->size(), -1),
      tree_of_(tree_->leaf_count()) {
  for (std::size_t leaf = 0; leaf < tree_->leaf_count(); ++leaf) {
    state_[leaf] = CutState::kActive;
    index_[leaf] = static_cast<std::int32_t>(leaf);
    tree_of_[leaf] = static_cast<TreeId>(leaf);
  }
  links_.reserve(net.links().size());
  for (const NetLink& l : net.links()) links_.push_back({l.a, l.b, LinkRole::kSteady, -1});
}

void take_snapshot(const btSoftBody& body, const CutView& cut, bool positions, std::int64_t step, CutSnapshot& out) {
  const int n = body.m_nodes.size();
  out.cut = cut;
  out.step = step;
  out.velocity.resize(static_cast<std::size_t>(n));
  out.position.resize(positions ? static_cast<std::size_t>(n) : 0);
  for (int i = 0; i < n; ++i) {
    const btVector3& v = body.m_nodes[i].m_v;
    out.velocity[static_cast<std::size_t>(i)] = {v.x(), v.y(), v.z()};
    if (positions) {
      const btVector3& x = body.m_nodes[i].m_x;
      out.position[static_cast<std::size_t>(i)] = {x.x(), x.y(), x.z()};
    }
  }
}

}  // namespace tcsb
