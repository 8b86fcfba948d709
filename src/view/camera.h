// Camera: where the spectator stands and what they see — a pinhole camera (position, target, up, vertical field of
// view, image size in pixels), optionally moving along a scripted path of keyframes. A scene states one (the
// suite's scene.camera); the BSWDF's view terms (feedback/saliency.h) and the fidelity pass's error in pixels
// (fidelity/screen_error.h) see the cloth through it, both by its projection (view/screen_projection.h). Plain data
// and its pose over time; no Bullet.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "../view/keyframe_path.h"

namespace tcsb {

/// Where the camera is and where it looks, metres.
struct CameraPose {
  std::array<double, 3> position{0, 0, 10};
  std::array<double, 3> target{0, 0, 0};
};

/// Why a pose gives no image, if it does not.
enum class CameraPoseProblem {
  kNone,
  kNoDirection,   ///< the position equals the target: the camera looks nowhere
  kLooksAlongUp,  ///< the viewing direction is parallel to up: the image has no up
};

/// The one rule for a usable pose, for the suite parser, validate_spectator and ScreenProjection alike. Parallel
/// means within 1e-6 of the product of the two lengths.
inline CameraPoseProblem camera_pose_problem(const CameraPose& pose, const std::array<double, 3>& up) {
  const std::array<double, 3> d{pose.target[0] - pose.position[0], pose.target[1] - pose.position[1],
                                pose.target[2] - pose.position[2]};
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 0)) return CameraPoseProblem::kNoDirection;
  const std::array<double, 3> side{d[1] * up[2] - d[2] * up[1], d[2] * up[0] - d[0] * up[2],
                                   d[0] * up[1] - d[1] * up[0]};
  const double up_length = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
  if (!(std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]) > 1e-6 * length * up_length))
    return CameraPoseProblem::kLooksAlongUp;
  return CameraPoseProblem::kNone;
}

/// One keyframe of a scripted camera path: the pose at `time` seconds of simulated time.
struct CameraKey {
  double time = 0;
  CameraPose pose;
};

/// A pose between two keyframes of a path that gives no image.
struct CameraPathProblem {
  std::size_t segment = 0;  ///< between keyframes `segment` and `segment + 1`
  double weight = 0;        ///< this far from one to the other, in (0, 1)
  double time = 0;          ///< seconds of simulated time
  CameraPoseProblem problem = CameraPoseProblem::kNone;
};

/// The worst pose strictly between two consecutive keyframes of `path`, where it gives no image (the keyframes
/// themselves are camera_pose_problem's to check). Every pose a path reaches is checked, not a sample of them: the
/// viewing direction d(w) = target(w) - position(w) is linear in the weight w, so is its cross product with up, c(w),
/// and camera_pose_problem's rule |c| > 1e-6 |d| |up| holds on the whole segment exactly when the quadratic
/// g(w) = |c(w)|^2 - 1e-12 |up|^2 |d(w)|^2 stays above 0 there; its minimum is at a vertex or an end. The pose at
/// the vertex, interpolated as Camera::pose_at interpolates it, is also put to camera_pose_problem itself, so
/// rounding cannot pass a pose the rule refuses. O(keyframes).
inline std::optional<CameraPathProblem> camera_path_problem(const std::vector<CameraKey>& path,
                                                            const std::array<double, 3>& up) {
  using V = std::array<double, 3>;
  const auto sub = [](const V& a, const V& b) { return V{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  const auto dot = [](const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const double k2 = 1e-12 * dot(up, up);
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const CameraPose& from = path[i].pose;
    const CameraPose& to = path[i + 1].pose;
    const V d0 = sub(from.target, from.position);
    const V e = sub(sub(to.target, to.position), d0);  // d(w) = d0 + w e
    const V c0 = cross(d0, up);
    const V f = sub(cross(sub(to.target, to.position), up), c0);  // c(w) = c0 + w f
    // g(w) = a w^2 + 2 b w + g(0): a minimum inside (0, 1) only when a > 0, at w = -b / a, of g(0) - b^2 / a.
    const double a = dot(f, f) - k2 * dot(e, e);
    const double b = dot(c0, f) - k2 * dot(d0, e);
    if (!(a > 0)) continue;
    const double w = -b / a;
    if (!(w > 0 && w < 1)) continue;
    const double g = dot(c0, c0) - k2 * dot(d0, d0) + w * b;
    const CameraPose pose{lerp(from.position, to.position, w), lerp(from.target, to.target, w)};
    CameraPoseProblem problem = camera_pose_problem(pose, up);
    if (problem == CameraPoseProblem::kNone && g <= 0) {
      // Refused by the exact rule though rounding passed the interpolated pose: name what it comes closest to.
      const V d = sub(pose.target, pose.position);
      problem = dot(d, d) <= 1e-18 * std::max(dot(d0, d0), dot(e, e)) ? CameraPoseProblem::kNoDirection
                                                                      : CameraPoseProblem::kLooksAlongUp;
    }
    if (problem != CameraPoseProblem::kNone)
      return CameraPathProblem{i, w, path[i].time + w * (path[i + 1].time - path[i].time), problem};
  }
  return std::nullopt;
}

struct Camera {
  CameraPose pose;                    ///< the pose when there is no path
  std::array<double, 3> up{0, 1, 0};  ///< world direction that appears upwards in the image (not along the view)
  double fov_deg = 45;                ///< vertical field of view, degrees, in (0, 180)
  int width_px = 1280;                ///< image size, pixels
  int height_px = 720;
  /// Keyframes, times strictly ascending; empty: the camera stands at `pose`. Between keyframes position and target
  /// move linearly; before the first and after the last the camera holds that keyframe's pose.
  std::vector<CameraKey> path;
  /// Occlusion: 0, not modelled (every point in view counts as seen); else points hidden behind the surface count as
  /// unseen, decided on a depth buffer of cells this many pixels wide (view/depth_buffer.h states what that costs),
  /// at most kMaxOcclusionCellPx: by the fidelity pass's error in pixels and by the feedback's view terms.
  int occlusion_cell_px = 0;
  /// Cells wider than this would judge a cloth's visibility by a handful of samples.
  static constexpr int kMaxOcclusionCellPx = 64;

  /// The pose at `time` seconds of simulated time.
  CameraPose pose_at(double time) const;
};

/// Who watches a body: the camera and the length of a step, so the feedback stage knows the camera's pose at each
/// step boundary (boundary b is at b x dt seconds).
struct Spectator {
  Camera camera;
  double dt = 1.0 / 60.0;
};

/// Throws std::invalid_argument naming the field ("Spectator: camera.path[1]: ...") when the spectator gives no image
/// at some time: a field of view outside (0, 180) degrees, an image without pixels, occlusion cells outside
/// [0, Camera::kMaxOcclusionCellPx], a zero or non-finite up, a non-finite position, target or time, keyframe times
/// not ascending, a pose (at a keyframe or between two: camera_path_problem) that looks nowhere or along up, or a
/// step length that is not a finite number > 0. What the suite parser refuses, for a library user who builds the
/// camera in code; make_controller checks with it.
void validate_spectator(const Spectator& spectator);

}  // namespace tcsb
