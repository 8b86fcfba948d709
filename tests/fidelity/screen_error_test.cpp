// The error in pixels: what the camera shows of two surfaces, and its summary over steps.
#include "fidelity/screen_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "../view/test_camera.h"

namespace tcsb {
namespace {

/// One metre sideways at the origin is 5 pixels (test_camera.h).
ScreenProjection view() { return {camera_looking_at_origin(), 0.0}; }

TEST(ScreenError, IdenticalSurfacesHaveNone) {
  const std::vector<Eigen::Vector3d> x{{0, 0, 0}, {1, 1, 0}, {-2, 0, 1}};
  std::vector<double> scratch;
  const ScreenError e = screen_error(view(), x, x, {}, scratch);
  EXPECT_EQ(e.in_view, 3u);
  EXPECT_EQ(e.mean, 0.0);
  EXPECT_EQ(e.max, 0.0);
}

TEST(ScreenError, CountsThePointsTheReferenceShowsInPixels) {
  const std::vector<Eigen::Vector3d> reference{{0, 0, 0}, {1, 0, 0}, {100, 0, 0}};
  // The first moves 1 m sideways (5 px), the second along the line of sight (0 px), the third is out of view.
  const std::vector<Eigen::Vector3d> subject{{1, 0, 0}, {1, 0, -0.0}, {0, 0, 0}};
  std::vector<double> scratch;
  const ScreenError e = screen_error(view(), subject, reference, {}, scratch);
  EXPECT_EQ(e.in_view, 2u);
  EXPECT_NEAR(e.mean, 2.5, 1e-12);
  EXPECT_NEAR(e.max, 5.0, 1e-12);
  EXPECT_NEAR(e.p95, 0.95 * 5.0, 1e-12);  // linear interpolation between the two
}

TEST(ScreenError, APointBehindTheCameraCountsAsTheDiagonal) {
  const std::vector<Eigen::Vector3d> reference{{0, 0, 0}}, subject{{0, 0, 20}};
  std::vector<double> scratch;
  EXPECT_DOUBLE_EQ(screen_error(view(), subject, reference, {}, scratch).max, std::hypot(200.0, 100.0));
}

TEST(ScreenError, APointTheSpectatorCannotSeeDoesNotCount) {
  const std::vector<Eigen::Vector3d> reference{{0, 0, 0}, {1, 0, 0}}, subject{{1, 0, 0}, {3, 0, 0}};
  const std::vector<std::uint8_t> seen{1, 0};  // the second is hidden: its 10 pixels are not seen
  std::vector<double> scratch;
  const ScreenError e = screen_error(view(), subject, reference, seen, scratch);
  EXPECT_EQ(e.in_view, 1u);
  EXPECT_NEAR(e.max, 5.0, 1e-12);
}

TEST(ScreenErrorSeries, SummarisesTheStepsThatShowSomething) {
  ScreenErrorSeries series;
  series.add({10, 0.5, 0.8, 1.0});
  series.add({0, 0, 0, 0});  // nothing in view: no screen error at that step
  series.add({30, 1.0, 2.0, 4.0});
  const ScreenMetrics m = series.finish();
  EXPECT_EQ(m.p95_px.count, 2u);
  EXPECT_DOUBLE_EQ(m.mean_px.mean, 0.75);
  EXPECT_DOUBLE_EQ(m.p95_px.mean, 1.4);
  EXPECT_DOUBLE_EQ(m.max_px.max, 4.0);
  EXPECT_DOUBLE_EQ(m.p95_over_1px_share, 0.5);
  EXPECT_DOUBLE_EQ(m.points_in_view, 40.0 / 3.0);
  EXPECT_EQ(ScreenErrorSeries().finish().p95_px.count, 0u);
}

}  // namespace
}  // namespace tcsb
