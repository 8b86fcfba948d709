// The one rule for which two links form a fan where a coarse block meets finer cloth: hanging interfaces pair links
// by it (tc_interfaces.cpp), and validate() checks by it that no fan is left unpaired (tc_validate.cpp).
#pragma once

#include "../net/lod_tree.h"
#include "../softbody/tc_softbody.h"

namespace tcsb {

/// Whether links `a` and `b`, both ending at the coarser node `coarse`, form a fan: made by the same operation in the
/// same role (tethers join a node to its own children, never a fan), their other ends two distinct siblings (the two
/// children of the block beside `coarse` that face it).
inline bool forms_fan(const LodTree& tree, TreeId coarse, const CutLink& a, const CutLink& b) {
  if (a.role != b.role || a.op != b.op || a.role == LinkRole::kTether) return false;
  const TreeId fa = a.other(coarse), fb = b.other(coarse);
  const LodNode& na = tree.node(fa);
  const LodNode& nb = tree.node(fb);
  return fa != fb && na.level == nb.level && na.parent == nb.parent;
}

}  // namespace tcsb
