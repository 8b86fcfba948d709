#include "feedback/camera.h"

#include <algorithm>

namespace tcsb {

CameraPose Camera::pose_at(double time) const {
  if (path.empty()) return pose;
  if (time <= path.front().time) return path.front().pose;
  if (time >= path.back().time) return path.back().pose;
  // The first keyframe later than `time`; its predecessor is at or before it (times ascend strictly).
  const auto next =
      std::upper_bound(path.begin(), path.end(), time, [](double t, const CameraKey& key) { return t < key.time; });
  const CameraKey& a = *(next - 1);
  const CameraKey& b = *next;
  const double w = (time - a.time) / (b.time - a.time);
  CameraPose out;
  for (std::size_t k = 0; k < 3; ++k) {
    out.position[k] = a.pose.position[k] + w * (b.pose.position[k] - a.pose.position[k]);
    out.target[k] = a.pose.target[k] + w * (b.pose.target[k] - a.pose.target[k]);
  }
  return out;
}

}  // namespace tcsb
