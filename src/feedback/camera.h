// Camera: where the spectator stands and what they see — a pinhole camera (position, target, up, vertical field of
// view, image size in pixels), optionally moving along a scripted path of keyframes. A scene states one (the
// suite's scene.camera); the BSWDF's view terms (feedback/screen_projection.h, saliency.h) and the fidelity pass's
// error in pixels see the cloth through it. Plain data and its pose over time; no Bullet.
#pragma once

#include <array>
#include <cmath>
#include <vector>

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

/// The one rule for a usable pose, for the suite parser and ScreenProjection alike (inline: the parser's library
/// does not link this one). Parallel means within 1e-6 of the product of the two lengths.
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

struct Camera {
  CameraPose pose;                    ///< the pose when there is no path
  std::array<double, 3> up{0, 1, 0};  ///< world direction that appears upwards in the image (not along the view)
  double fov_deg = 45;                ///< vertical field of view, degrees, in (0, 180)
  int width_px = 1280;                ///< image size, pixels
  int height_px = 720;
  /// Keyframes, times strictly ascending; empty: the camera stands at `pose`. Between keyframes position and target
  /// move linearly; before the first and after the last the camera holds that keyframe's pose.
  std::vector<CameraKey> path;

  /// The pose at `time` seconds of simulated time.
  CameraPose pose_at(double time) const;
};

/// Who watches a body: the camera and the length of a step, so the feedback stage knows the camera's pose at each
/// step boundary (boundary b is at b x dt seconds).
struct Spectator {
  Camera camera;
  double dt = 1.0 / 60.0;
};

}  // namespace tcsb
