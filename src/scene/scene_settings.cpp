#include "scene/scene_settings.h"

namespace tcsb {

std::string collider_name(const Collider& collider) {
  const char* motion = collider.motion == ColliderMotion::kStatic      ? "static"
                       : collider.motion == ColliderMotion::kKinematic ? "kinematic"
                                                                       : "dynamic";
  const char* shape = collider.shape == ColliderShape::kSphere ? "sphere"
                      : collider.shape == ColliderShape::kBox  ? "box"
                                                               : "plane";
  return std::string(motion) + " " + shape;
}

}  // namespace tcsb
