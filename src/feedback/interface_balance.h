// Interface balance: how a candidate operation changes the boundaries between cut levels around it.
//
// Where a coarse block meets finer cloth, Bullet's links fan from the block's one node to the two finer nodes on
// each side. The fan is not the fine cloth's material: it pulls the finer rows together under tension, and no single
// link stiffness per level mends it (docs/methodology.md, "Interfaces between levels"). A cut's error therefore grows
// with the boundaries between its levels, not only with how coarse it is: scattered isolated blocks err far more than
// one coarse region of the same size. The evaluator can weigh each candidate by the boundaries it would add or remove
// (FeedbackSettings::interface_charge).
#pragma once

#include <span>

#include "../feedback/cut_snapshot.h"

namespace tcsb {

/// For the tree node `id`, the sum over its four same-level grid neighbours (those that exist) of +1 when the cloth at
/// the neighbour's place is simulated at the neighbour's level or coarser (the neighbour or one of its ancestors is
/// committed), and -1 when it is finer. Range [-4, 4]. Coarsening `id`'s children into `id` removes a level boundary
/// on each +1 side and adds one on each -1 side; refining `id` does the opposite. O(levels).
int neighbour_balance(const CutView& cut, TreeId id);

/// The level most of the cloth must take under a budget of `budget` simulated nodes: with n_l the node count of the
/// whole cut at level l, a budget between n_(l+1) and n_l holds a share (budget - n_(l+1)) / (n_l - n_(l+1)) of the
/// net at level l and the rest at level l + 1; the level holding at least half. 0 when the whole net fits; the tree's
/// top level when the budget is below every other level's count. O(levels).
int budget_level(const LodTree& tree, int budget);

/// How the evaluator charges a candidate for the level boundaries it adds or removes.
struct InterfaceCharge {
  double per_boundary = 0;  ///< c (FeedbackSettings::interface_charge); 0: off
  /// Per tree node, how much its boundaries weigh (feedback/pin_tension.h: more near the pins); empty: 1 everywhere.
  std::span<const float> weight;
  /// p (FeedbackSettings::pin_level_pull) and budget_level(): where the weight w exceeds 1, the cloth of the budget's
  /// level counts as one more neighbour of weight p (w - 1). 0: none.
  double pull = 0;
  int budget_level = 0;

  /// The factor exp(-c (w b + p (w - 1) s) / 4) on the priority of refining or coarsening into `id`: b its
  /// neighbour_balance, s +1 when the budget's level is id's level or coarser and -1 when finer. A positive sum (the
  /// operation adds boundaries, or moves the cloth away from the budget's level) lowers it. 1 when off.
  double factor(const CutView& cut, TreeId id) const;
};

}  // namespace tcsb
