// CutSnapshot: what the feedback stage reads of a body. The cut's topology is read in place (it only changes at
// step boundaries, never while Bullet steps); the motion is copied at the boundary, so saliency can be evaluated on
// worker threads while Bullet steps the body on (the paper evaluates its TreeCut in parallel, §5).
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "net/lod_tree.h"
#include "net/net.h"
#include "softbody/tc_softbody.h"

namespace tcsb {

/// A cut through a LOD tree as flat arrays (borrowed, not owned).
struct CutView {
  const LodTree* tree = nullptr;
  std::span<const CutState> state;      ///< per tree node
  std::span<const std::int32_t> index;  ///< per tree node: simulated node index, or -1
  std::span<const TreeId> tree_of;      ///< per simulated node
  std::span<const CutLink> links;       ///< the simulated links (those with joins_committed() are the cut's adjacency)

  bool committed(TreeId id) const {
    const CutState s = state[static_cast<std::size_t>(id)];
    return s == CutState::kActive || s == CutState::kArriving;
  }
  std::size_t size() const { return tree_of.size(); }
};

/// The view of a TC-SB body's cut.
CutView cut_view(const TcSoftBody& body);

/// The finest cut (every leaf active, simulated node i = leaf i, the net's links), as a stock body built from the
/// net has it.
class FinestCut {
 public:
  explicit FinestCut(const Net& net);
  CutView view() const { return {tree_, state_, index_, tree_of_, links_}; }

 private:
  const LodTree* tree_;
  std::vector<CutState> state_;
  std::vector<std::int32_t> index_;
  std::vector<TreeId> tree_of_;
  std::vector<CutLink> links_;
};

/// A cut and its nodes' motion at one step boundary.
struct CutSnapshot {
  CutView cut;
  std::vector<std::array<float, 3>> velocity;  ///< per simulated node
  std::vector<std::array<float, 3>> position;  ///< per simulated node (only when illumination needs normals)
  std::int64_t step = -1;                      ///< the boundary it was taken at

  std::size_t size() const { return cut.size(); }
};

/// Copies the body's velocities (and positions when `positions`): O(N), memcpy-like. Reuses the buffers.
void take_snapshot(const btSoftBody& body, const CutView& cut, bool positions, std::int64_t step, CutSnapshot& out);

}  // namespace tcsb
