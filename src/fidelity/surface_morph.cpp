#include "fidelity/surface_morph.h"

#include "fidelity/reconstruction.h"

namespace tcsb {

void SurfaceMorph::reconstruct(const TcSoftBody& body, std::vector<Eigen::Vector3d>& leaves) {
  reconstruct_leaves(body, leaves);
  if (body.interpolations() == 0) {  // nothing blends: no jump left to spread, and no need to look for one
    jumps_.clear();
    return;
  }
  const LodTree& tree = body.tree();
  // Operations that ended: their blocks show the committed cut alone now.
  for (auto it = jumps_.begin(); it != jumps_.end();)
    it = body.state(it->first) == CutState::kArriving ? std::next(it) : jumps_.erase(it);
  for (int i = 0; i < body.node_count(); ++i) {
    const TreeId id = body.tree_id(i);
    if (body.state(id) != CutState::kArriving) continue;
    const double w = body.arrival_weight(id);
    Jump& jump = jumps_[id];
    if (jump.offset.empty() || w < jump.weight) {  // first seen: record the jump the operation makes
      old_.resize(leaves.size());
      reconstruct_from_leaving(body, id, old_);
      jump.offset.clear();
      for_each_leaf(tree, id, [&](TreeId leaf) {
        const auto l = static_cast<std::size_t>(leaf);
        jump.offset.push_back(old_[l] - leaves[l]);
      });
    }
    jump.weight = w;
    std::size_t k = 0;
    for_each_leaf(tree, id,
                  [&](TreeId leaf) { leaves[static_cast<std::size_t>(leaf)] += (1.0 - w) * jump.offset[k++]; });
  }
}

}  // namespace tcsb
