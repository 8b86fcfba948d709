#include "feedback/cut_snapshot.h"

namespace tcsb {

CutView cut_view(const TcSoftBody& body) {
  const btVector3& pins = body.pin_offset();
  return {&body.tree(),    body.states(),    body.bullet_indices(),
          body.tree_ids(), body.cut_links(), {pins.x(), pins.y(), pins.z()}};
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

void take_snapshot(const btSoftBody& body, const CutView& cut, bool positions, std::int64_t step, CutSnapshot& out,
                   const std::vector<TreeId>* contacts) {
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
  out.contact.assign(contacts ? static_cast<std::size_t>(n) : 0, 0);
  if (!contacts) return;
  // A node the operations have taken out of the cut since the step has no index; one they brought in has no contact
  // yet (it gets one from the next step).
  for (const TreeId id : *contacts) {
    const std::int32_t i = cut.index[static_cast<std::size_t>(id)];
    if (i >= 0) out.contact[static_cast<std::size_t>(i)] = 1;
  }
}

void nodes_in_contact(const btSoftBody& body, std::span<const TreeId> tree_of, std::vector<TreeId>& out) {
  out.clear();
  if (body.m_nodes.size() == 0) return;
  const btSoftBody::Node* first = &body.m_nodes[0];
  for (int c = 0; c < body.m_rcontacts.size(); ++c) {
    const std::ptrdiff_t i = body.m_rcontacts[c].m_node - first;
    if (i >= 0 && static_cast<std::size_t>(i) < tree_of.size()) out.push_back(tree_of[static_cast<std::size_t>(i)]);
  }
}

}  // namespace tcsb
