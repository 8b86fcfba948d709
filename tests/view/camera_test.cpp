// The camera: poses along a path, and the poses a path reaches that give no image.
#include "view/camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "test_camera.h"
#include "view/screen_projection.h"

namespace tcsb {
namespace {

TEST(Camera, StandsStillWithoutAPath) {
  const Camera c = camera_looking_at_origin();
  EXPECT_EQ(c.pose_at(0).position, c.pose.position);
  EXPECT_EQ(c.pose_at(1e6).target, c.pose.target);
}

TEST(Camera, MovesLinearlyBetweenKeyframesAndHoldsOutside) {
  Camera c = camera_looking_at_origin();
  c.path = {{1.0, {{0, 0, 10}, {0, 0, 0}}}, {3.0, {{4, 0, 10}, {2, 0, 0}}}, {4.0, {{4, 8, 10}, {2, 0, 0}}}};
  EXPECT_DOUBLE_EQ(c.pose_at(0.0).position[0], 0.0);  // before the first keyframe: its pose
  EXPECT_DOUBLE_EQ(c.pose_at(2.0).position[0], 2.0);
  EXPECT_DOUBLE_EQ(c.pose_at(2.0).target[0], 1.0);
  EXPECT_DOUBLE_EQ(c.pose_at(3.5).position[1], 4.0);
  EXPECT_DOUBLE_EQ(c.pose_at(9.0).position[1], 8.0);  // after the last: its pose
  EXPECT_DOUBLE_EQ(c.pose_at(3.0).position[0], 4.0);  // on a keyframe: exactly it
}

TEST(CameraPath, FindsTheCraneShotThatLooksAlongUpBetweenValidKeyframes) {
  // Ten metres apart, five above the target, looking down at it from either side: halfway it looks straight down.
  const std::vector<CameraKey> path{{0.0, {{0, 5, -5}, {0, 0, 0}}}, {2.0, {{0, 5, 5}, {0, 0, 0}}}};
  const std::array<double, 3> up{0, 1, 0};
  ASSERT_EQ(camera_pose_problem(path[0].pose, up), CameraPoseProblem::kNone);
  ASSERT_EQ(camera_pose_problem(path[1].pose, up), CameraPoseProblem::kNone);
  const std::optional<CameraPathProblem> bad = camera_path_problem(path, up);
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->segment, 0u);
  EXPECT_NEAR(bad->weight, 0.5, 1e-12);
  EXPECT_NEAR(bad->time, 1.0, 1e-12);
  EXPECT_EQ(bad->problem, CameraPoseProblem::kLooksAlongUp);
  Camera c = camera_looking_at_origin();
  c.path = path;
  EXPECT_THROW(ScreenProjection(c, bad->time), std::invalid_argument) << "the pose the run would have met";
  // Passing a metre beside the point above the target, the camera never looks straight down.
  const std::vector<CameraKey> aside{{0.0, {{1, 5, -5}, {0, 0, 0}}}, {2.0, {{1, 5, 5}, {0, 0, 0}}}};
  EXPECT_FALSE(camera_path_problem(aside, up));
  // The second segment of three is the bad one; the position running through the target looks nowhere.
  const std::vector<CameraKey> through{
      {0.0, {{0, 0, 5}, {0, 0, 0}}}, {1.0, {{0, 0, 4}, {0, 0, 0}}}, {3.0, {{0, 0, -4}, {0, 0, 0}}}};
  const std::optional<CameraPathProblem> nowhere = camera_path_problem(through, up);
  ASSERT_TRUE(nowhere);
  EXPECT_EQ(nowhere->segment, 1u);
  EXPECT_NEAR(nowhere->time, 2.0, 1e-12);
  EXPECT_EQ(nowhere->problem, CameraPoseProblem::kNoDirection);
}

TEST(CameraPath, AgreesWithDenseSamplingOnRandomPaths) {
  // Small integer coordinates make paths through the target or along up common. Whatever pose a dense sampling of
  // a segment finds refused, the analysis finds too (it checks every pose, not samples); what the analysis finds,
  // the pose rule itself refuses.
  std::mt19937 rng(60);
  std::uniform_int_distribution<int> coordinate(-2, 2);
  const auto point = [&] {
    return std::array<double, 3>{double(coordinate(rng)), double(coordinate(rng)), double(coordinate(rng))};
  };
  int sampled_bad = 0, found = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::array<double, 3> up = point();
    if (up == std::array<double, 3>{}) up = {0, 1, 0};
    std::vector<CameraKey> path;
    while (path.size() < 2) {
      const CameraPose pose{point(), point()};
      if (camera_pose_problem(pose, up) == CameraPoseProblem::kNone)
        path.push_back({static_cast<double>(path.size()), pose});
    }
    bool bad = false;
    for (int k = 1; k < 1000 && !bad; ++k) {
      const double w = k / 1000.0;
      bad = camera_pose_problem({lerp(path[0].pose.position, path[1].pose.position, w),
                                 lerp(path[0].pose.target, path[1].pose.target, w)},
                                up) != CameraPoseProblem::kNone;
    }
    const std::optional<CameraPathProblem> problem = camera_path_problem(path, up);
    sampled_bad += bad;
    found += problem.has_value();
    if (bad) {
      EXPECT_TRUE(problem) << "trial " << trial;
    }
    if (problem) {
      const CameraPose pose{lerp(path[0].pose.position, path[1].pose.position, problem->weight),
                            lerp(path[0].pose.target, path[1].pose.target, problem->weight)};
      // The rule refuses the interpolated pose; or rounding left a direction of a few ulps where the exact pose
      // has none (the position passing through the target), and the analysis says so.
      const CameraPoseProblem rule = camera_pose_problem(pose, up);
      if (rule == CameraPoseProblem::kNone) {
        EXPECT_EQ(problem->problem, CameraPoseProblem::kNoDirection) << "trial " << trial;
        const auto length = [](const CameraPose& p) {
          return std::hypot(p.target[0] - p.position[0], p.target[1] - p.position[1], p.target[2] - p.position[2]);
        };
        EXPECT_LT(length(pose), 1e-12 * std::max(length(path[0].pose), length(path[1].pose))) << "trial " << trial;
      } else {
        EXPECT_EQ(rule, problem->problem) << "trial " << trial;
      }
    }
  }
  EXPECT_GT(sampled_bad, 50) << "the random paths should meet bad poses often";
  EXPECT_GE(found, sampled_bad);
}

}  // namespace
}  // namespace tcsb
