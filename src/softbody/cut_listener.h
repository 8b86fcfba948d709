// CutListener: what an application hears of a TreeCut soft body's cut as it changes.
#pragma once

#include "../net/lod_tree.h"
#include "../softbody/op_kind.h"

namespace tcsb {

/// Told by a TcSoftBody (set_cut_listener) of each change to its cut, right after the body made it, on the thread
/// that made it. An application that keeps something per simulated node — a render mesh, a texture coordinate, an
/// attachment of its own — updates it here instead of comparing the cut with last frame's. Bullet indices may have
/// changed in any call (removals fill their hole with the last node), so read them again (TcSoftBody::bullet_index,
/// tree_id). A listener must not change the body.
class CutListener {
 public:
  virtual ~CutListener() = default;
  /// An operation on `block` ran: kRefine, `block`'s children joined Bullet beside it and begin to blend in;
  /// kCoarse, `block` joined beside its children; kEndRefine, `block` left Bullet (its children stay); kEndCoarse,
  /// its children left (`block` stays).
  virtual void cut_changed(OpKind kind, TreeId block) = 0;
  /// Bullet's node and link arrays were put back into a plain body's order (TcSoftBody::restore_order): every
  /// simulated node may have a new Bullet index; the cut itself is unchanged.
  virtual void arrays_reordered() {}
};

}  // namespace tcsb
