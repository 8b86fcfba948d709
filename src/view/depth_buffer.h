// DepthBuffer: what the camera sees first. The image is cut into square cells of `cell_px` pixels; each cell holds
// the depth of the nearest triangle covering the cell's centre. A point in view is hidden when a triangle covers its
// cell more than a tolerance nearer than the point: the spectator cannot see it, so its error should not count
// (fidelity/screen_error.h) and its detail is worth nothing (the view terms, feedback/saliency.h).
//
// What the approximations cost, stated so a caller can choose them:
// - Cells: a point's visibility is its cell centre's. Points within one cell (cell_px pixels) of an occluder's
//   silhouette may be misjudged either way; with cell_px = 1 the buffer is the camera's own resolution.
// - Tolerance: a surface and the point on it are told apart by depth alone, so a layer less than `tolerance` metres
//   in front of a point does not hide it (a cloth's own triangles around a node sit at about the node's depth; seen
//   edge-on, its neighbours within the cell are up to a link's length nearer, so a tolerance of about one link keeps
//   a surface from hiding itself, and merges folds closer than that into one layer).
// - The near plane: a triangle with a corner at or behind it is left out — it hides nothing, so a point may count
//   as visible that a surface grazing the lens would hide, never the other way round.
// Depth is interpolated perspective-correctly (1/depth is linear across the image). O(cells covered) per triangle.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

#include "../view/screen_projection.h"

namespace tcsb {

class DepthBuffer {
 public:
  /// An empty buffer for `view`'s image in cells of `cell_px` pixels. Throws std::invalid_argument when cell_px < 1.
  DepthBuffer(const ScreenProjection& view, int cell_px);

  /// Forgets every triangle. O(cells inside the box around the triangles added since the last clear), not O(image):
  /// a cloth far from the lens covers a few cells of an image the feedback clears at every evaluation.
  void clear();
  /// Adds the triangle whose corners appear at a, b and c (their images through this buffer's view).
  void add_triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c);
  /// Whether the point whose image is `p` can be seen: in view, and no triangle covers its cell more than
  /// `tolerance` metres nearer than it.
  bool visible(const ScreenPoint& p, double tolerance) const;

  int columns() const { return columns_; }
  int rows() const { return rows_; }

 private:
  int cell_px_ = 1;
  int columns_ = 0, rows_ = 0;
  std::vector<float> nearest_;  // row-major; +infinity where no triangle covers the cell's centre
  // The box of cells that may hold a triangle's depth (empty: first > last), which clear() resets.
  int dirty_i0_ = 0, dirty_i1_ = -1, dirty_j0_ = 0, dirty_j1_ = -1;
};

/// Which points of one or more grids the camera sees: `points` are whole grids of width x height points one after
/// another (each row-major; several cloths of one net, say), whose surfaces are their quads, each split along one
/// diagonal. Clears `buffer` (whose view is `view`), draws every grid's surface into it, so each hides the others,
/// then writes visible[i] = 1 for each point in view and not hidden by any surface (DepthBuffer::visible with
/// `tolerance`), else 0. Throws std::invalid_argument when points is empty or not a whole number of grids.
void visible_grid_points(const ScreenProjection& view, std::span<const Eigen::Vector3d> points, int width, int height,
                         double tolerance, DepthBuffer& buffer, std::vector<std::uint8_t>& visible);

}  // namespace tcsb
