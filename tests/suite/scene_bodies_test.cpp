// scene.bodies and feedback.budget_scope: a scene of many bodies is read, its bodies placed, and each bad input is
// refused naming its field.
#include "suite/scene_bodies.h"

#include <gtest/gtest.h>

#include <string>

#include "../world/world_suite_json.h"
#include "base/input_error.h"
#include "net/net.h"

namespace tcsb {
namespace {

using nlohmann::json;
using testing::world_suite_json;

/// The message parsing `j` fails with ("" when it parses).
std::string scene_bodies_failure(const json& j) {
  try {
    parse_suite_text(j.dump(), "row.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneBodies, AreReadAndPlacedWhereTheyStand) {
  const Suite s = parse_suite_text(world_suite_json().dump(), "row.json");
  ASSERT_TRUE(is_world_suite(s));
  EXPECT_EQ(s.feedback.budget_scope, BudgetScope::kWorld);
  const std::vector<NetSpec> placed = scene_body_nets(s);
  ASSERT_EQ(placed.size(), 3u);
  EXPECT_EQ(placed[2].centre_x, 3.0);
  EXPECT_EQ(placed[2].elevation, 2.0);
  EXPECT_EQ(placed[2].width, 9);
  const Net net(placed[0]);
  EXPECT_DOUBLE_EQ(net.rest_positions()[0].x(), -3.5);  // the rest rectangle's corner, 0.5 m left of the centre
}

TEST(SceneBodies, DefaultIsOneCaseOneCloth) {
  json j = world_suite_json();
  j["scene"].erase("bodies");
  j["feedback"].erase("budget_scope");
  const Suite s = parse_suite_text(j.dump(), "row.json");
  EXPECT_FALSE(is_world_suite(s));
  EXPECT_EQ(s.feedback.budget_scope, BudgetScope::kBody);
}

TEST(SceneBodies, RefusesAnEmptyList) {
  json j = world_suite_json();
  j["scene"]["bodies"] = json::array();
  EXPECT_NE(scene_bodies_failure(j).find("scene.bodies"), std::string::npos);
}

TEST(SceneBodies, RefusesBodiesThatOverlapAtStepZero) {
  json j = world_suite_json();
  j["scene"]["bodies"][1]["position"] = {-2.5, 2.0, 0.25};
  EXPECT_NE(scene_bodies_failure(j).find("scene.bodies[1].position"), std::string::npos);
}

TEST(SceneBodies, RefusesACameraOfOneKeyframe) {
  json j = world_suite_json();
  j["scene"]["camera"]["path"].erase(1);
  EXPECT_NE(scene_bodies_failure(j).find("scene.camera.path"), std::string::npos);
}

TEST(SceneBodies, RefusesAWorldBudgetWithoutTcsbBodies) {
  json j = world_suite_json();
  j["scene"].erase("bodies");
  EXPECT_NE(scene_bodies_failure(j).find("feedback.budget_scope"), std::string::npos);
  j = world_suite_json();
  j["methods"] = {"plain"};
  j.erase("compression");
  EXPECT_NE(scene_bodies_failure(j).find("feedback.budget_scope"), std::string::npos);
}

TEST(SceneBodies, RefusesAnUnknownNet) {
  json j = world_suite_json();
  j["scene"]["bodies"][2]["net"] = "nope";
  EXPECT_NE(scene_bodies_failure(j).find("scene.bodies[2].net"), std::string::npos);
}

}  // namespace
}  // namespace tcsb
