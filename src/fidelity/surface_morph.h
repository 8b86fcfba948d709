// SurfaceMorph: TC-SB's reconstructed surface with each operation's jump spread over its blend — a geomorph (Hoppe,
// "Progressive Meshes", SIGGRAPH 1996, §4.2), as the paper's link blending spreads the physical change.
//
// When an operation begins, its block's surface would jump from what the leaving nodes show to what the arriving
// ones show. The morph records that jump per leaf, D = old - new, the first time it sees the operation, and then
// shows new + (1 - w) D, w the weight the operation's fading-in links carry (1/(K+1) at its start, rising by
// 1/(K+1) per step, 1 when it ends). So the surface moves by D/(K+1) per step boundary instead of D at once, while
// following the new nodes' motion. The jump is frozen, not recomputed from the leaving nodes each step: those are
// still simulated while their links fade, and drift from the surface (measured: mixing them in step by step popped
// 1.2-2.0 % of the net's extent at the worst step, docs/methodology.md, "Tried and left out").
#pragma once

#include <Eigen/Core>

#include <unordered_map>
#include <vector>

#include "softbody/tc_softbody.h"

namespace tcsb {

/// The geomorphed surface of one TC-SB body. Stateful: call reconstruct() at every step boundary, after its
/// operations began (and as often as wanted in between), so that it sees each operation at its first step.
class SurfaceMorph {
 public:
  /// Every leaf of the body: reconstruct_leaves() of the committed cut, plus the unspent part of each blending
  /// operation's jump. `leaves` is resized to the net's node count. O(N + cut size x degree).
  void reconstruct(const TcSoftBody& body, std::vector<Eigen::Vector3d>& leaves);

 private:
  /// An operation's jump at its arriving node: one offset per leaf of the node's block, in for_each_leaf() order.
  struct Jump {
    double weight = 0;  ///< the arrival weight last seen: a lower one means a new operation at the same node
    std::vector<Eigen::Vector3d> offset;
  };
  std::unordered_map<TreeId, Jump> jumps_;
  std::vector<Eigen::Vector3d> old_;  // scratch: the leaving nodes' surface of a new operation's block
};

}  // namespace tcsb
