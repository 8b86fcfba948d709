// UnseenBody: whether the spectator can see any of a body, judged from a snapshot in O(N) with an O(1) test per
// camera — so an evaluation of a body nobody sees can be made cheaper or rarer (feedback.view_unseen_interval;
// docs/investigations/street-world-budget.md). Nodes out of view already rank at the off-screen floor and corners
// out of view show no jump (feedback/saliency.h, feedback/coarse_jump.h); this tells when that holds for the whole
// body, before any node's view terms are computed.
#pragma once

#include <span>

#include "../feedback/cut_snapshot.h"
#include "../view/screen_projection.h"

namespace tcsb {

/// True when no point of the body's reconstructed surface can be in view in any of `views`: the box around the
/// snapshot's nodes (positions required), grown on every side by the side of the largest block the cut simulates —
/// a block's corners, where the popping charge measures its jumps, lie within that of its node — is beyond the view
/// (ScreenProjection::may_see_box) of each. False for an empty snapshot.
bool unseen_in(const CutSnapshot& snapshot, std::span<const ScreenProjection> views);

}  // namespace tcsb
