#include "fidelity/surface_morph.h"

#include "fidelity/reconstruction.h"

namespace tcsb {

void SurfaceMorph::boundary(const TcSoftBody& body) {
  const int boundaries = spread(body);
  for (auto it = jumps_.begin(); it != jumps_.end();)  // one boundary older; spent ones go
    it = ++it->age >= boundaries ? jumps_.erase(it) : std::next(it);
  std::vector<Eigen::Vector3d> before;
  before.swap(raw_);
  reconstruct_leaves(body, raw_);
  fresh_ = true;
  if (before.size() != raw_.size()) return;  // nothing reconstructed yet: no jump to measure
  Jump jump;
  for (std::size_t l = 0; l < raw_.size(); ++l) {
    const Eigen::Vector3d d = before[l] - raw_[l];
    if (d.isZero(0.0)) continue;  // exactly unchanged: the block and its fit are the same
    jump.leaf.push_back(static_cast<std::int32_t>(l));
    jump.offset.push_back(d);
  }
  if (!jump.leaf.empty()) jumps_.push_back(std::move(jump));
}

void SurfaceMorph::reconstruct(const TcSoftBody& body, std::vector<Eigen::Vector3d>& leaves) {
  if (!fresh_) reconstruct_leaves(body, raw_);
  fresh_ = false;
  leaves = raw_;
  const double boundaries = spread(body);
  for (const Jump& jump : jumps_) {
    const double unspent = 1.0 - jump.age / boundaries;
    for (std::size_t k = 0; k < jump.leaf.size(); ++k)
      leaves[static_cast<std::size_t>(jump.leaf[k])] += unspent * jump.offset[k];
  }
}

}  // namespace tcsb
