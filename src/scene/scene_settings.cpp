#include "scene/scene_settings.h"

namespace tcsb {

std::string collider_name(const Collider& collider) {
  const char* motion = collider.motion == ColliderMotion::kStatic      ? "static"
                       : collider.motion == ColliderMotion::kKinematic ? "kinematic"
                                                                       : "dynamic";
  const char* shape = collider.shape == ColliderShape::kSphere ? "sphere"
                      : collider.shape == ColliderShape::kBox  ? "box"
                                                               : "plane";
  std::string name = std::string(motion) + " " + shape;
  if (!collider.path.empty()) name += " on a path of " + std::to_string(collider.path.size()) + " keyframes";
  return name;
}

const char* aero_model_name(AeroModel model) {
  switch (model) {
    case AeroModel::kVPoint: return "V_Point";
    case AeroModel::kVTwoSided: return "V_TwoSided";
    case AeroModel::kVTwoSidedLiftDrag: return "V_TwoSidedLiftDrag";
    case AeroModel::kVOneSided: return "V_OneSided";
    case AeroModel::kFTwoSided: return "F_TwoSided";
    case AeroModel::kFTwoSidedLiftDrag: return "F_TwoSidedLiftDrag";
    case AeroModel::kFOneSided: return "F_OneSided";
  }
  return "?";
}

}  // namespace tcsb
