// ScreenProjection: the camera at one moment as a map from the world to its image — where a point appears (pixels,
// origin at the image's top-left corner, y downwards), whether it is in view, and how fast a motion moves across
// the image. The one projection of the cloth: the BSWDF's view terms (feedback/saliency.h) and the fidelity pass's
// error in pixels (fidelity/screen_error.h) both see it through this. Pure geometry: O(1) per point.
#pragma once

#include <Eigen/Core>

#include <array>

#include "../view/camera.h"

namespace tcsb {

/// Points nearer to the camera's plane than this (metres) are not in view: a pinhole camera's image of a point at
/// depth d scales with 1/d, which is unbounded at the lens.
inline constexpr double kNearPlane = 0.01;

/// A point's image.
struct ScreenPoint {
  double x = 0, y = 0;   ///< pixels; meaningless unless depth >= kNearPlane
  double depth = 0;      ///< metres along the viewing direction (negative: behind the camera)
  bool in_view = false;  ///< in front of the near plane and inside the image
};

class ScreenProjection {
 public:
  /// The camera's view at `time` seconds of simulated time (Camera::pose_at). Throws std::invalid_argument when the
  /// position equals the target or `up` lies along the viewing direction (the parser refuses both).
  ScreenProjection(const Camera& camera, double time);

  ScreenPoint project(const Eigen::Vector3d& x) const;
  ScreenPoint project(const std::array<float, 3>& x) const { return project(Eigen::Vector3d(x[0], x[1], x[2])); }

  /// How fast a point at `x` moving with velocity `v` crosses the image, pixels per second: the projection's
  /// derivative applied to v (motion along the line of sight moves nothing), so a motion far away or seen end-on
  /// is slow. 0 at or behind the near plane.
  double pixel_speed(const Eigen::Vector3d& x, const Eigen::Vector3d& v) const;

  /// How long a segment of `length` metres at `x`, across the line of sight, appears on the image, pixels. 0 at or
  /// behind the near plane.
  double apparent_size_px(const Eigen::Vector3d& x, double length) const;
  /// The same were the camera turned to look at x (the length over its distance from the eye, anywhere around it):
  /// how large something out of view or behind the camera would look once the camera turns to it.
  double facing_size_px(const Eigen::Vector3d& x, double length) const;

  /// Visual angle of one pixel at the image's centre, degrees: turns pixel speeds into the retinal velocities of
  /// the perception literature (Yee, Pattanaik and Greenberg 2001).
  double degrees_per_pixel() const { return degrees_per_pixel_; }
  /// Length of the image's diagonal, pixels: the largest displacement two points in view can have.
  double diagonal_px() const;
  /// The image's size, pixels.
  double width_px() const { return width_; }
  double height_px() const { return height_; }
  /// How far from `seen_in_view` (a point's image, in view) the point `x` appears, pixels; where `x` is at or behind
  /// the near plane it has no image, and counts as the image's diagonal.
  double displacement_px(const Eigen::Vector3d& x, const ScreenPoint& seen_in_view) const;

 private:
  Eigen::Vector3d eye_, right_, up_, forward_;
  double focal_px_ = 1;  // image distance of the pinhole, pixels
  double width_ = 1, height_ = 1;
  double degrees_per_pixel_ = 1;
};

/// The camera as it stands after `steps` steps of `dt` seconds, at steps x dt: the image the state after those steps
/// is seen in (the end of step s is s + 1 steps). One rule for the fidelity pass, the world pass and their tests.
inline ScreenProjection view_after_steps(const Camera& camera, int steps, double dt) {
  return ScreenProjection(camera, static_cast<double>(steps) * dt);
}

}  // namespace tcsb
