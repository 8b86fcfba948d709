// The camera at one moment: where points appear, what is in view, how fast a motion crosses the image, how big a
// block looks, how far apart two images of a point are.
#include "view/screen_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "test_camera.h"

namespace tcsb {
namespace {

TEST(ScreenProjection, ThePointLookedAtIsTheImagesCentre) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  const ScreenPoint p = view.project(Eigen::Vector3d(0, 0, 0));
  EXPECT_TRUE(p.in_view);
  EXPECT_DOUBLE_EQ(p.x, 100.0);
  EXPECT_DOUBLE_EQ(p.y, 50.0);
  EXPECT_DOUBLE_EQ(p.depth, 10.0);
  // One metre right at ten metres: 5 pixels right (focal 50 px); one metre up: 5 pixels up (y grows downwards).
  EXPECT_NEAR(view.project(Eigen::Vector3d(1, 0, 0)).x, 105.0, 1e-12);
  EXPECT_NEAR(view.project(Eigen::Vector3d(0, 1, 0)).y, 45.0, 1e-12);
}

TEST(ScreenProjection, WhatIsBehindOrBesideTheImageIsNotInView) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  EXPECT_FALSE(view.project(Eigen::Vector3d(0, 0, 11)).in_view) << "behind the camera";
  EXPECT_FALSE(view.project(Eigen::Vector3d(0, 0, 10)).in_view) << "at the lens";
  EXPECT_FALSE(view.project(Eigen::Vector3d(25, 0, 0)).in_view) << "125 px right of the centre of a 200 px image";
  EXPECT_TRUE(view.project(Eigen::Vector3d(19, 0, 0)).in_view);
  EXPECT_FALSE(view.project(Eigen::Vector3d(0, 11, 0)).in_view) << "55 px above the centre of a 100 px image";
}

TEST(ScreenProjection, PixelSpeedIsTheProjectionsDerivative) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  const Eigen::Vector3d x(2, -1, 3), v(0.3, 0.7, -1.1);
  const double h = 1e-6;
  const ScreenPoint a = view.project(x), b = view.project(x + h * v);
  EXPECT_NEAR(view.pixel_speed(x, v), std::hypot(b.x - a.x, b.y - a.y) / h, 1e-4);
  // Along the line of sight nothing moves on the image; sideways, the speed falls with the distance.
  EXPECT_NEAR(view.pixel_speed(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1)), 0.0, 1e-12);
  EXPECT_NEAR(view.pixel_speed(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0)), 5.0, 1e-12);
  EXPECT_NEAR(view.pixel_speed(Eigen::Vector3d(0, 0, -10), Eigen::Vector3d(1, 0, 0)), 2.5, 1e-12);
  EXPECT_EQ(view.pixel_speed(Eigen::Vector3d(0, 0, 12), Eigen::Vector3d(1, 0, 0)), 0.0) << "behind the camera";
  EXPECT_DOUBLE_EQ(view.degrees_per_pixel(), 0.9);
}

TEST(ScreenProjection, ApparentSizeFallsWithDistance) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  EXPECT_DOUBLE_EQ(view.apparent_size_px(Eigen::Vector3d(0, 0, 0), 2.0), 10.0);
  EXPECT_DOUBLE_EQ(view.apparent_size_px(Eigen::Vector3d(0, 0, -10), 2.0), 5.0);
  EXPECT_EQ(view.apparent_size_px(Eigen::Vector3d(0, 0, 20), 2.0), 0.0);
  EXPECT_DOUBLE_EQ(view.diagonal_px(), std::hypot(200.0, 100.0));
}

TEST(ScreenProjection, DisplacementIsTheDistanceOnTheImageOrTheDiagonal) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  const ScreenPoint origin = view.project(Eigen::Vector3d(0, 0, 0));
  EXPECT_NEAR(view.displacement_px(Eigen::Vector3d(3, 4, 0), origin), 25.0, 1e-12) << "15 px right, 20 px up";
  EXPECT_EQ(view.displacement_px(Eigen::Vector3d(0, 0, 0), origin), 0.0);
  // Behind the camera, or at the lens, a point has no image: the largest displacement there is.
  EXPECT_EQ(view.displacement_px(Eigen::Vector3d(0, 0, 12), origin), view.diagonal_px());
  EXPECT_EQ(view.displacement_px(Eigen::Vector3d(0, 0, 10), origin), view.diagonal_px());
}

TEST(ScreenProjection, FollowsThePath) {
  Camera c = camera_looking_at_origin();
  c.path = {{0.0, {{0, 0, 10}, {0, 0, 0}}}, {1.0, {{30, 0, 10}, {30, 0, 0}}}};
  EXPECT_TRUE(ScreenProjection(c, 0.0).project(Eigen::Vector3d(0, 0, 0)).in_view);
  EXPECT_FALSE(ScreenProjection(c, 1.0).project(Eigen::Vector3d(0, 0, 0)).in_view) << "the camera moved away";
  EXPECT_DOUBLE_EQ(ScreenProjection(c, 1.0).project(Eigen::Vector3d(30, 0, 0)).x, 100.0);
}

TEST(ScreenProjection, RefusesACameraWithoutADirection) {
  Camera c = camera_looking_at_origin();
  c.pose.target = c.pose.position;
  EXPECT_THROW(ScreenProjection(c, 0), std::invalid_argument);
  c = camera_looking_at_origin();
  c.up = {0, 0, 1};  // along the viewing direction
  EXPECT_THROW(ScreenProjection(c, 0), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
