// Conversions between Bullet's single-precision vectors and the double-precision Eigen vectors the nets, the
// placement fits and the fidelity measures use.
#pragma once

#include <LinearMath/btVector3.h>

#include <Eigen/Core>

namespace tcsb {

/// Exact: every float is a double.
inline Eigen::Vector3d to_eigen(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

/// Rounds each coordinate to Bullet's btScalar.
inline btVector3 to_bullet(const Eigen::Vector3d& v) {
  return {static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()), static_cast<btScalar>(v.z())};
}

}  // namespace tcsb
