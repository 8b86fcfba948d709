// The least-squares affine map from rest offsets in the net's plane to current offsets: the one rule that child
// placement (TcSoftBody::local_affine_fit), the reconstruction and the feedback's jump estimate
// (feedback/coarse_jump.h) all use, so an estimate follows what it predicts.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <optional>
#include <span>

#include "../net/lod_tree.h"

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

/// Where a block's node appears when its children coarsen into it, if it does not rest at their centre of mass (a
/// block on the net's border rests on that border, LodTree::rest()): the children's mass-weighted affine fit from
/// their rest positions to their positions x, evaluated at the block's rest position. Children on one line fit
/// rigidly (solve_affine_fit). begin_coarse and the feedback's jump estimate (feedback/coarse_jump.cpp) both use it.
inline Eigen::Vector3d fitted_arrival(std::span<const Eigen::Vector3d> x, std::span<const Eigen::Vector3d> rest,
                                      std::span<const double> mass, const Eigen::Vector3d& block_rest) {
  Eigen::Vector3d xm = Eigen::Vector3d::Zero(), rm = Eigen::Vector3d::Zero();
  double m = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    xm += mass[i] * x[i];
    rm += mass[i] * rest[i];
    m += mass[i];
  }
  xm /= m;
  rm /= m;
  Eigen::Matrix2d rr = Eigen::Matrix2d::Zero();
  Eigen::Matrix<double, 3, 2> xr = Eigen::Matrix<double, 3, 2>::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Eigen::Vector2d r(rest[i].x() - rm.x(), rest[i].z() - rm.z());
    rr += mass[i] * r * r.transpose();
    xr += mass[i] * (x[i] - xm) * r.transpose();
  }
  return xm + solve_affine_fit(rr, xr) * Eigen::Vector2d(block_rest.x() - rm.x(), block_rest.z() - rm.z());
}

/// Where `parent`'s node appears when its children, at positions `child_x` (in children order), coarsen into it, if
/// that is not their centre of mass: fitted_arrival() for a block without a pin that rests off its centroid (on the
/// net's border, or anywhere with RestPlacement::kVertex); nullopt for every other block (and for children without
/// mass). The one rule of begin_coarse and the
/// feedback's jump estimate.
inline std::optional<Eigen::Vector3d> border_arrival(const LodTree& tree, TreeId parent,
                                                     std::span<const Eigen::Vector3d> child_x) {
  const LodNode& p = tree.node(parent);
  if (p.pinned() || !tree.may_rest_off_centroid(p) || tree.rest(parent) == tree.centroid(parent)) return std::nullopt;
  std::array<Eigen::Vector3d, 4> rest;
  std::array<double, 4> mass;
  double total = 0;
  for (int k = 0; k < p.child_count; ++k) {
    const TreeId c = p.children[static_cast<std::size_t>(k)];
    rest[static_cast<std::size_t>(k)] = tree.rest(c);
    mass[static_cast<std::size_t>(k)] = tree.node(c).mass;
    total += tree.node(c).mass;
  }
  if (total <= 0) return std::nullopt;
  const auto n = static_cast<std::size_t>(p.child_count);
  return fitted_arrival(child_x.first(n), {rest.data(), n}, {mass.data(), n}, tree.rest(parent));
}

}  // namespace tcsb
