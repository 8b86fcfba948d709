// Evaluator: the TreeCut evaluation — turns per-node saliency into ranked refine and coarse candidates.
//
// A cut node X at level k that is coarser than the leaves stands for a 2^k-wide block; rendering it with one node
// costs detail in proportion to how salient it is and how big it is, so its refine priority is S(X) * 2^k. A
// parent P whose children are all in the cut would, once merged, cost max over children S(c) * 2^level(P): its
// coarse priority (lower is better to coarsen). The controller pairs them under the budget with the paper's
// threshold (§5): a node is inserted only if its gain exceeds the penalty of the removal it forces plus the
// threshold, so nothing flips back and forth. Optionally a coarse candidate is also charged with the jump its
// coarsen would make the reconstructed surface pop by (feedback/coarse_jump.h), so curved blocks are merged last,
// and every candidate with the level boundaries it would add (feedback/interface_balance.h).
#pragma once

#include <span>
#include <vector>

#include "../feedback/coarse_jump.h"
#include "../feedback/cut_snapshot.h"
#include "../feedback/interface_balance.h"

namespace tcsb {

/// A tree node and its priority.
struct Candidate {
  double priority = 0;
  TreeId id = kNoTreeNode;
};

/// Ranked candidates from one snapshot.
struct Evaluation {
  std::vector<Candidate> refine;  ///< active non-leaf cut nodes, highest priority first
  std::vector<Candidate> coarse;  ///< parents whose children are all active, lowest priority first
  std::int64_t snapshot_step = -1;
};

/// What a coarse candidate is charged for the jump it would cause (FeedbackSettings::popping_charge).
struct JumpCharge {
  double per_pct = 0;  ///< priority added per 1 % of `extent` that the surface would jump; 0 charges nothing
  double extent = 1;   ///< the net's extent, metres
  const CutNeighbours* neighbours = nullptr;  ///< the snapshot's cut adjacency; required when either charge > 0
  /// Priority added per pixel the surface would jump on `view`'s image (coarse_jump_px; FeedbackSettings::
  /// view_popping_charge); 0 charges nothing. Adds to the charge per %.
  double per_px = 0;
  const ScreenProjection* view = nullptr;  ///< the spectator's camera; required when per_px > 0
};

/// Ranks at most `limit` candidates of each kind (ties broken by a hash of the tree id: deterministic, and spread
/// over the net).
/// With a charge, each coarse candidate's priority grows by per_pct x its jump in % of the extent and per_px x its
/// jump in pixels on the view's image (the snapshot must hold positions). With an interface charge c > 0, every
/// candidate's priority is multiplied by exp(-c w b / 4), where b is its neighbour_balance
/// (feedback/interface_balance.h) and w its weight there (1, or more near the pins: feedback/pin_tension.h): coarsens
/// that merge a block into coarser surroundings go sooner, coarsens that leave an isolated block later, and refines
/// likewise the other way round.
void rank_candidates(const CutSnapshot& snapshot, std::span<const float> saliency, int limit, Evaluation& out,
                     const JumpCharge& charge = {}, const InterfaceCharge& interface = {});

}  // namespace tcsb
