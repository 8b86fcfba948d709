// What discrete LOD switches on: the camera's distance to each body, and with a look-ahead the nearer of the
// camera's now and then (suite/world_plan.h), so discrete LOD sees the future TC-SB's view terms see.
#include "suite/world_plan.h"

#include <gtest/gtest.h>

#include <cmath>

#include "world_suite_json.h"

namespace tcsb {
namespace {

std::vector<double> distances_with_lookahead(double seconds, int steps) {
  nlohmann::json j = testing::world_suite_json();
  j["feedback"]["view_lookahead_s"] = seconds;
  return lod_camera_distances(parse_suite_text(j.dump(), "row.json"), steps);
}

TEST(LodCameraDistances, AreTheCameraToEachBodyAtTheEndOfEachStep) {
  // The camera starts at (-3, 1.5, -2) and reaches (3, 1.5, -2) at 0.75 s; the banners are placed at x = -3, 0 and
  // 3, 2 m high, z = 0. After one step the camera is 6 / 45 m along.
  const std::vector<double> d = distances_with_lookahead(0.0, 2);
  ASSERT_EQ(d.size(), 6u);
  const double along = 6.0 / 0.75 / 60.0;
  EXPECT_NEAR(d[0], std::hypot(along, 0.5, 2.0), 1e-9);
  EXPECT_NEAR(d[2], std::hypot(6.0 - along, 0.5, 2.0), 1e-9);
}

TEST(LodCameraDistances, WithALookAheadAreTheNearerOfNowAndThen) {
  const int steps = 45;
  const std::vector<double> now = distances_with_lookahead(0.0, steps);
  const std::vector<double> ahead = distances_with_lookahead(0.25, steps);
  ASSERT_EQ(now.size(), ahead.size());
  int nearer = 0;
  for (std::size_t i = 0; i < now.size(); ++i) {
    EXPECT_LE(ahead[i], now[i]) << i;
    const std::size_t later = i + 15 * 3;  // 0.25 s is 15 steps of 3 bodies later
    if (later < now.size()) {
      EXPECT_DOUBLE_EQ(ahead[i], std::min(now[i], now[later])) << i;
    }
    nearer += ahead[i] < now[i];
  }
  EXPECT_GT(nearer, 0);  // the camera approaches the last banners: they look nearer ahead of time
}

}  // namespace
}  // namespace tcsb
