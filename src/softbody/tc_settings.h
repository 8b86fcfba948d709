// TcSettings: how a TreeCut soft body performs its operations.
#pragma once

namespace tcsb {

/// Where refine places the children of a node.
enum class Placement {
  kAffine,  ///< parent position + local deformation (least-squares affine fit over the neighbourhood) x rest offset
  kRigid,   ///< parent position + rest offset (the paper's placement)
};

/// Settings of the TreeCut soft body's operations.
struct TcSettings {
  int blend_steps = 5;  ///< K: steps over which leaving links fade out and arriving links fade in
  Placement placement = Placement::kAffine;
};

}  // namespace tcsb
