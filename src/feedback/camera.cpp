#include "feedback/camera.h"

#include "feedback/keyframe_path.h"

namespace tcsb {

CameraPose Camera::pose_at(double time) const {
  if (path.empty()) return pose;
  const KeyframeSpan s = keyframe_span(path, time);
  const CameraPose& a = path[s.from].pose;
  const CameraPose& b = path[s.to].pose;
  return {lerp(a.position, b.position, s.weight), lerp(a.target, b.target, s.weight)};
}

}  // namespace tcsb
