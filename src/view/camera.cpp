#include "view/camera.h"

#include "view/keyframe_path.h"

#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tcsb {

CameraPose Camera::pose_at(double time) const {
  if (path.empty()) return pose;
  const KeyframeSpan s = keyframe_span(path, time);
  const CameraPose& a = path[s.from].pose;
  const CameraPose& b = path[s.to].pose;
  return {lerp(a.position, b.position, s.weight), lerp(a.target, b.target, s.weight)};
}

namespace {

[[noreturn]] void refuse(const std::string& field, const std::string& problem) {
  throw std::invalid_argument("Spectator: " + field + ": " + problem);
}

std::string text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// The field's name is `field` + `part`, spelt out only when refused: a game tells the spectator every frame, and
// building the names of fields that pass cost as much as the checks.
void check_finite(std::string_view field, std::string_view part, const std::array<double, 3>& v) {
  for (const double c : v)
    if (!std::isfinite(c)) refuse(std::string(field).append(part), "must be finite, got " + text(c));
}

void check_pose(std::string_view field, const CameraPose& pose, const std::array<double, 3>& up) {
  check_finite(field, ".position", pose.position);
  check_finite(field, ".target", pose.target);
  switch (camera_pose_problem(pose, up)) {
    case CameraPoseProblem::kNoDirection:
      refuse(std::string(field) + ".target", "equals the position (the camera looks nowhere)");
    case CameraPoseProblem::kLooksAlongUp:
      refuse(std::string(field) + ".target", "the camera looks along up (the image has no up)");
    case CameraPoseProblem::kNone: break;
  }
}

}  // namespace

void validate_spectator(const Spectator& spectator) {
  const Camera& c = spectator.camera;
  if (!(std::isfinite(spectator.dt) && spectator.dt > 0))
    refuse("dt", "must be a finite number > 0, got " + text(spectator.dt));
  if (!(c.fov_deg > 0 && c.fov_deg < 180)) refuse("camera.fov_deg", "must be in (0, 180), got " + text(c.fov_deg));
  if (c.width_px < 1 || c.height_px < 1)
    refuse("camera.width_px",
           "the image must have pixels, got " + std::to_string(c.width_px) + " x " + std::to_string(c.height_px));
  if (c.occlusion_cell_px < 0 || c.occlusion_cell_px > Camera::kMaxOcclusionCellPx)
    refuse("camera.occlusion_cell_px", "must be 0 (off) or 1 to " + std::to_string(Camera::kMaxOcclusionCellPx) +
                                           " pixels, got " + std::to_string(c.occlusion_cell_px));
  check_finite("camera.up", "", c.up);
  if (c.up == std::array<double, 3>{}) refuse("camera.up", "must not be the zero vector");
  if (c.path.empty()) {
    check_pose("camera.pose", c.pose, c.up);
    return;
  }
  for (std::size_t i = 0; i < c.path.size(); ++i) {
    const std::string at = "camera.path[" + std::to_string(i) + "]";
    if (!std::isfinite(c.path[i].time)) refuse(at + ".time", "must be finite, got " + text(c.path[i].time));
    if (i > 0 && !(c.path[i].time > c.path[i - 1].time))
      refuse(at + ".time", "must be later than the keyframe before (" + text(c.path[i - 1].time) + ")");
    check_pose(at, c.path[i].pose, c.up);
  }
  if (const std::optional<CameraPathProblem> bad = camera_path_problem(c.path, c.up))
    refuse("camera.path[" + std::to_string(bad->segment + 1) + "]",
           "on the way from the keyframe before, at time " + text(bad->time) + " s, the camera " +
               (bad->problem == CameraPoseProblem::kNoDirection ? "looks nowhere (position meets target)"
                                                                : "looks along up (the image has no up)"));
}

}  // namespace tcsb
