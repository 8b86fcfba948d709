#include "view/screen_projection.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tcsb {

namespace {
Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
}  // namespace

ScreenProjection::ScreenProjection(const Camera& camera, double time) {
  const CameraPose pose = camera.pose_at(time);
  switch (camera_pose_problem(pose, camera.up)) {
    case CameraPoseProblem::kNoDirection: throw std::invalid_argument("camera: position equals target");
    case CameraPoseProblem::kLooksAlongUp: throw std::invalid_argument("camera: up lies along the viewing direction");
    case CameraPoseProblem::kNone: break;
  }
  eye_ = vec(pose.position);
  forward_ = (vec(pose.target) - eye_).normalized();
  right_ = forward_.cross(vec(camera.up)).normalized();
  up_ = right_.cross(forward_);
  width_ = camera.width_px;
  height_ = camera.height_px;
  const double half_fov = camera.fov_deg * std::numbers::pi / 360.0;
  focal_px_ = 0.5 * height_ / std::tan(half_fov);
  degrees_per_pixel_ = camera.fov_deg / height_;
}

ScreenPoint ScreenProjection::project(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d d = x - eye_;
  ScreenPoint p;
  p.depth = d.dot(forward_);
  if (p.depth < kNearPlane) return p;
  p.x = 0.5 * width_ + focal_px_ * d.dot(right_) / p.depth;
  p.y = 0.5 * height_ - focal_px_ * d.dot(up_) / p.depth;
  p.in_view = p.x >= 0 && p.x <= width_ && p.y >= 0 && p.y <= height_;
  return p;
}

double ScreenProjection::pixel_speed(const Eigen::Vector3d& x, const Eigen::Vector3d& v) const {
  const Eigen::Vector3d d = x - eye_;
  const double z = d.dot(forward_);
  if (z < kNearPlane) return 0;
  // u = f (d.r) / z: du/dt = f ((v.r) z - (d.r)(v.f)) / z^2, likewise for the image's vertical axis.
  const double vz = v.dot(forward_);
  const double du = focal_px_ * (v.dot(right_) * z - d.dot(right_) * vz) / (z * z);
  const double dv = focal_px_ * (v.dot(up_) * z - d.dot(up_) * vz) / (z * z);
  return std::sqrt(du * du + dv * dv);
}

double ScreenProjection::apparent_size_px(const Eigen::Vector3d& x, double length) const {
  const double z = (x - eye_).dot(forward_);
  return z < kNearPlane ? 0.0 : focal_px_ * length / z;
}

double ScreenProjection::facing_size_px(const Eigen::Vector3d& x, double length) const {
  const double distance = (x - eye_).norm();
  return distance < kNearPlane ? 0.0 : focal_px_ * length / distance;
}

double ScreenProjection::diagonal_px() const { return std::sqrt(width_ * width_ + height_ * height_); }

double ScreenProjection::displacement_px(const Eigen::Vector3d& x, const ScreenPoint& seen_in_view) const {
  const ScreenPoint p = project(x);
  return p.depth >= kNearPlane ? std::hypot(p.x - seen_in_view.x, p.y - seen_in_view.y) : diagonal_px();
}

}  // namespace tcsb
