// Screen error: a reconstructed surface's error as the spectator sees it. Both surfaces are projected through the
// scene's camera at the same moment; for every grid point the reference shows in view, the distance on the image
// between where the reference puts it and where the subject does, in pixels. A world-space error of 1 % of the net is
// invisible on a cloth twenty metres away and glaring a metre from the lens; this is the measure that tells them
// apart. With the camera's occlusion on, a point the reference's own surface hides does not count: the spectator
// cannot see where it is (view/depth_buffer.h).
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fidelity/fidelity_result.h"
#include "view/screen_projection.h"

namespace tcsb {

/// One step's screen error, over the grid points the reference shows (all 0 when it shows none).
struct ScreenError {
  std::size_t in_view = 0;            ///< grid points of the reference in view and, with occlusion, not hidden
  double mean = 0, p95 = 0, max = 0;  ///< pixels
};

/// The screen error of `subject` against `reference` (the same grid points, in the same order) seen through `view`,
/// each point's ScreenProjection::displacement_px (a subject point without an image counts as the image's
/// diagonal). `seen`, when not empty, says which reference points the spectator sees (visible_grid_points); the
/// others do not count. `scratch` is reused between calls.
ScreenError screen_error(const ScreenProjection& view, std::span<const Eigen::Vector3d> subject,
                         std::span<const Eigen::Vector3d> reference, std::span<const std::uint8_t> seen,
                         std::vector<double>& scratch);

/// The per-step screen errors of a subject over the measured steps, summarised into ScreenMetrics. Steps whose
/// reference shows nothing in view have no screen error and are left out of the summaries.
class ScreenErrorSeries {
 public:
  void add(const ScreenError& e);
  ScreenMetrics finish() const;

 private:
  std::vector<double> mean_, p95_, max_, in_view_;
};

}  // namespace tcsb
