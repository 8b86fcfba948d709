// CoarseJump: how far a coarsen would make the reconstructed surface jump, estimated from a snapshot — so the
// evaluator can charge it (docs/design.md, "The feedback loop"; issue 20, part 4).
//
// The fidelity pass shows TC-SB's surface as every committed node's block placed by the node's local affine fit
// (fidelity/reconstruction.h). Coarsening parent P replaces its children's blocks, each bent by its own fit, with
// one block placed by P's fit: on curved cloth the surface jumps by the curvature the one affine map cannot hold.
// The geomorph spreads that jump over the blend, but only divides it by K + 1; a large jump still pops. This file
// computes the jump the reconstruction would record when the coarsen begins: at every corner leaf of every child's
// block (the largest distance between two affine maps over a rectangle is at a corner), the distance between
//   before: x_c + F_c (r_leaf - r_c), F_c the child's fit over its cut neighbours (exactly x_c for a leaf child),
//   after:  x_P + F_P (r_leaf - r_P), x_P where begin_coarse puts P (the children's centre of mass, or its rest
//           position when it holds a pinned leaf) and F_P the fit over what P is linked to while it arrives: the
//           children's neighbours outside the block and the children themselves.
// Measured in metres, or in pixels on the spectator's image (coarse_jump_px): a jump of a centimetre is glaring a
// metre from the lens and invisible twenty metres away or off-screen, and under one world budget the charge then
// moves coarsens to where the spectator cannot see them. Reads only the snapshot (positions copied at a step
// boundary) and the cut's topology, so it can run on a feedback worker while Bullet steps.
#pragma once

#include <cstdint>
#include <vector>

#include "../feedback/cut_snapshot.h"
#include "../view/screen_projection.h"

namespace tcsb {

/// The committed cut's adjacency per simulated node (links joining two committed nodes), compressed rows: node i's
/// neighbours are other[start[i] .. start[i + 1]). Built in link order: the same on every run.
struct CutNeighbours {
  std::vector<std::int32_t> start;  ///< size() + 1 entries
  std::vector<std::int32_t> other;  ///< simulated node indices
};

/// Fills `out` from the cut's links. O(N + L); reuses the buffers.
void cut_neighbours(const CutView& cut, CutNeighbours& out);

/// The largest distance, in metres, the reconstructed surface would move over `parent`'s block if the parent were
/// coarsened now (before the geomorph spreads it). `parent`'s children must all be in the snapshot's cut, and the
/// snapshot must hold positions. O(children x degree).
double coarse_jump(const CutSnapshot& snapshot, const CutNeighbours& neighbours, TreeId parent);

/// The same jump as the spectator would see it on `view`'s image, pixels: at every corner whose place before the
/// coarsen is in view, the distance on the image to its place after (ScreenProjection::displacement_px); corners out
/// of view or behind the camera show no jump. The snapshot's positions must be in the camera's world frame.
double coarse_jump_px(const CutSnapshot& snapshot, const CutNeighbours& neighbours, TreeId parent,
                      const ScreenProjection& view);

}  // namespace tcsb
