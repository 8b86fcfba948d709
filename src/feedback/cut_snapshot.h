// CutSnapshot: what the feedback stage reads of a body. The cut's topology is read in place (it only changes at
// step boundaries, never while Bullet steps); the motion is copied at the boundary, so saliency can be evaluated on
// worker threads while Bullet steps the body on (the paper evaluates its TreeCut in parallel, §5).
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "../net/lod_tree.h"
#include "../net/net.h"
#include "../softbody/tc_softbody.h"

namespace tcsb {

/// A cut through a LOD tree as flat arrays (borrowed, not owned).
struct CutView {
  const LodTree* tree = nullptr;
  std::span<const CutState> state;      ///< per tree node
  std::span<const std::int32_t> index;  ///< per tree node: simulated node index, or -1
  std::span<const TreeId> tree_of;      ///< per simulated node
  std::span<const CutLink> links;       ///< the simulated links (those with joins_committed() are the cut's adjacency)
  /// Where the pins are, as an offset from their rest positions (TcSoftBody::pin_offset: the scene's pin path moved
  /// them); a pinned node sits at its rest position plus this. Zero for pins at rest.
  std::array<float, 3> pin_offset{0, 0, 0};

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
  CutView view() const { return {tree_, state_, index_, tree_of_, links_, {0, 0, 0}}; }

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
  /// Per simulated node, 1 when Bullet's last step found it in contact with a rigid body (nodes_in_contact); empty
  /// unless the contact feature asked for it.
  std::vector<std::uint8_t> contact;
  /// The body's surface, its cut's faces as simulated-node index triples (SurfaceOcclusion::capture); empty unless
  /// the spectator's camera models occlusion.
  std::vector<std::array<std::int32_t, 3>> faces;
  std::int64_t step = -1;  ///< the boundary it was taken at

  std::size_t size() const { return cut.size(); }
};

/// Copies the body's velocities (and positions when `positions`): O(N), memcpy-like. Reuses the buffers. With
/// `contacts` (tree nodes, from nodes_in_contact) it marks those of them the cut simulates now: O(N + contacts).
void take_snapshot(const btSoftBody& body, const CutView& cut, bool positions, std::int64_t step, CutSnapshot& out,
                   const std::vector<TreeId>* contacts = nullptr);

/// The tree nodes Bullet found in contact with a rigid body in the body's last step (its rigid contacts, whose node
/// pointers hold only until the cut next changes: call this right after the step), `tree_of` mapping simulated node
/// indices to tree nodes. O(contacts); a node in several contacts is listed once per contact.
void nodes_in_contact(const btSoftBody& body, std::span<const TreeId> tree_of, std::vector<TreeId>& out);

}  // namespace tcsb
