// The least-squares affine map from rest offsets in the net's plane to current offsets: the one rule that child
// placement (TcSoftBody::local_affine_fit), the reconstruction and the feedback's jump estimate
// (feedback/coarse_jump.h) all use, so an estimate follows what it predicts.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

namespace tcsb {

/// F (3x2) minimising sum |dx - F dr|^2, from the sums rr = sum dr dr^T and xr = sum dx dr^T. Points on one line
/// (or none) leave the plane undetermined: the identity-in-plane [[1,0],[0,0],[0,1]], the rigid offset, then.
inline Eigen::Matrix<double, 3, 2> solve_affine_fit(const Eigen::Matrix2d& rr, const Eigen::Matrix<double, 3, 2>& xr) {
  Eigen::Matrix<double, 3, 2> f;
  f << 1, 0, 0, 0, 0, 1;
  const double scale = rr.trace();
  if (scale > 0 && rr.determinant() > 1e-6 * scale * scale) f = xr * rr.inverse();
  return f;
}

}  // namespace tcsb
