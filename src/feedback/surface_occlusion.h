// SurfaceOcclusion: which simulated nodes the spectator sees past the body's own surface, for the view terms
// (saliency.h: a hidden node gets the lowest saliency, as a node out of view does). Only when the spectator's camera
// models occlusion (Camera::occlusion_cell_px > 0); without it nothing here runs and the saliency is as before.
//
// The surface is TC-SB's committed cut triangulated as its faces are (softbody/tc_faces.cpp), captured at the step
// boundary on the simulation thread, where the cut is stable; the depth buffer is drawn from the snapshot on the
// evaluation's thread. Cost per evaluation: O(leaves) to capture (the faces' owner map) and O(nodes + cells covered)
// to draw and test.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "../feedback/cut_snapshot.h"
#include "../view/depth_buffer.h"
#include "../view/screen_projection.h"

namespace tcsb {

class SurfaceOcclusion {
 public:
  /// Writes the body's committed cut's faces into snapshot.faces as simulated-node index triples (snapshot.cut must
  /// be the body's cut_view). Between steps only: the cut must not change while this reads it.
  void capture(const TcSoftBody& body, CutSnapshot& snapshot);

  /// Per simulated node, 1 when `view` sees it: in view, and no face of snapshot.faces covers its cell of a depth
  /// buffer of `cell_px` pixels more than the node's own block side nearer than it. The tolerance is the block's
  /// side (block_side, saliency.h) because a coarse block's faces are chords a block's side long: where the cloth
  /// bends within that span, the faces around a node can pass up to about that much in front of it in its cell, as
  /// a link's do on the finest cut, and must not hide the node they are drawn from. On the finest cut it is one
  /// link, as the fidelity pass's visible_grid_points has it; the cost: a fold closer than a block's side does not
  /// hide a coarse node.
  /// Requires snapshot positions. The buffer is kept between calls and made anew only when the image's cells change.
  std::span<const std::uint8_t> seen(const CutSnapshot& snapshot, const ScreenProjection& view, int cell_px);

 private:
  std::vector<std::array<TreeId, 3>> tree_faces_;  // capture()'s scratch
  std::vector<TreeId> owner_;                      // capture()'s scratch: one entry per leaf
  std::optional<DepthBuffer> buffer_;
  std::array<double, 3> buffer_key_{0, 0, 0};  // the cell and image size buffer_ was made for
  std::vector<ScreenPoint> image_;
  std::vector<std::uint8_t> seen_;
};

}  // namespace tcsb
