// The world pass recorded for the fly-by animation, on a tiny scene of two banners: the frames' shape, the levels
// each method gives its grid points, and that recording changes none of the pass's figures.
#include "world/world_frames.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "world/world_runner.h"
#include "world_suite_json.h"

namespace tcsb {
namespace {

/// Two of the row's banners, 20 warm-up and 20 measured steps, TC-SB and discrete LOD at 30 % of the nodes.
Suite two_banners() {
  nlohmann::json j = testing::world_suite_json();
  j["scene"]["bodies"].erase(2);
  j["compression"] = {1.0, 0.3};
  j["steps"] = 20;
  return parse_suite_text(j.dump(), "two.json");
}

const std::vector<int> kRecordedSteps{0, 10, 20, 30, 40};

class WorldFramesOfTwoBanners : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    suite_ = new Suite(two_banners());
    frames_ = new WorldFrames(record_world_frames(*suite_, 0.3, kRecordedSteps));
  }
  static void TearDownTestSuite() {
    delete frames_;
    delete suite_;
  }
  static const WorldFrameScene& scene(std::size_t frame, const std::string& method) {
    for (std::size_t m = 0; m < frames_->methods.size(); ++m)
      if (frames_->methods[m].method == method) return frames_->frames[frame].scenes[m];
    throw std::runtime_error("no method " + method);
  }
  static Suite* suite_;
  static WorldFrames* frames_;
};
Suite* WorldFramesOfTwoBanners::suite_ = nullptr;
WorldFrames* WorldFramesOfTwoBanners::frames_ = nullptr;

TEST_F(WorldFramesOfTwoBanners, HoldEveryBodysGridPointsAndLevelsAtEachStep) {
  ASSERT_EQ(frames_->bodies.size(), 2u);
  ASSERT_EQ(frames_->methods.size(), 2u);
  EXPECT_EQ(frames_->methods[0].method, "tcsb_world");
  EXPECT_EQ(frames_->methods[1].method, "discrete_lod");
  ASSERT_EQ(frames_->frames.size(), kRecordedSteps.size());
  for (std::size_t f = 0; f < kRecordedSteps.size(); ++f) {
    const WorldFrame& frame = frames_->frames[f];
    EXPECT_EQ(frame.step, kRecordedSteps[f]);
    ASSERT_EQ(frame.scenes.size(), 2u);
    for (const WorldFrameScene& s : frame.scenes) {
      ASSERT_EQ(s.surfaces.size(), 2u);
      ASSERT_EQ(s.levels.size(), 2u);
      for (std::size_t b = 0; b < 2; ++b) {
        EXPECT_EQ(s.surfaces[b].size(), 81u);
        ASSERT_EQ(s.levels[b].size(), 81u);
        // A 9 x 9 net's tree has levels 0..4 (9, 5, 3, 2, 1 nodes a side); discrete LOD's grids are 0..3.
        for (const int level : s.levels[b]) {
          EXPECT_GE(level, 0);
          EXPECT_LE(level, 4);
        }
      }
      EXPECT_GT(s.nodes, 0);
      EXPECT_LE(s.nodes, 2 * 81);
    }
  }
}

TEST_F(WorldFramesOfTwoBanners, TcsbStartsFineAndCoarsensToItsBudget) {
  for (const std::vector<int>& levels : scene(0, "tcsb_world").levels)
    EXPECT_TRUE(std::all_of(levels.begin(), levels.end(), [](int l) { return l == 0; }));
  const WorldFrameScene& last = scene(kRecordedSteps.size() - 1, "tcsb_world");
  int coarse = 0;
  for (const std::vector<int>& levels : last.levels)
    coarse += static_cast<int>(std::count_if(levels.begin(), levels.end(), [](int l) { return l > 0; }));
  EXPECT_GT(coarse, 0);
  EXPECT_LT(last.nodes, 2 * 81);
}

TEST_F(WorldFramesOfTwoBanners, DiscreteLodGivesEachBodyOneLevel) {
  for (std::size_t f = 0; f < kRecordedSteps.size(); ++f)
    for (const std::vector<int>& levels : scene(f, "discrete_lod").levels) {
      EXPECT_EQ(std::count(levels.begin(), levels.end(), levels.front()), 81);
      EXPECT_LE(levels.front(), 3);
    }
}

TEST_F(WorldFramesOfTwoBanners, RecordingChangesNoneOfThePassFigures) {
  Suite one_budget = *suite_;
  one_budget.compression = {0.3};
  const WorldResult plain = run_world(one_budget);
  for (const WorldMethodResult& recorded : frames_->methods) {
    const auto m = std::find_if(plain.methods.begin(), plain.methods.end(),
                                [&](const WorldMethodResult& r) { return r.method == recorded.method; });
    ASSERT_NE(m, plain.methods.end()) << recorded.method;
    EXPECT_EQ(m->status, recorded.status) << recorded.method;
    EXPECT_EQ(m->mean_nodes, recorded.mean_nodes) << recorded.method;
    EXPECT_EQ(m->body_mean_nodes, recorded.body_mean_nodes) << recorded.method;
    EXPECT_EQ(m->p95_px, recorded.p95_px) << recorded.method;
    EXPECT_EQ(m->popping_px, recorded.popping_px) << recorded.method;
    EXPECT_EQ(m->resolution_changes, recorded.resolution_changes) << recorded.method;
  }
}

TEST(WorldFrames, OfASuiteWithCurvesHoldTheOneBudgetOnly) {
  // The street asks for curves: their budgets' scenes carry the same methods' names and must not be recorded.
  nlohmann::json j = testing::world_suite_json();
  j["scene"]["bodies"].erase(2);
  j["compression"] = {1.0, 0.3};
  j["steps"] = 20;
  j["fidelity"] = {{"curves", {{"budgets", {0.5}}, {"solver_divisors", {2}}}}};
  const WorldFrames with_curves = record_world_frames(parse_suite_text(j.dump(), "curves.json"), 0.3, {0, 40});
  ASSERT_EQ(with_curves.methods.size(), 2u);
  const WorldFrames without = record_world_frames(two_banners(), 0.3, {0, 40});
  for (std::size_t m = 0; m < 2; ++m) {
    EXPECT_EQ(with_curves.methods[m].budget, 0.3);
    EXPECT_EQ(with_curves.methods[m].mean_nodes, without.methods[m].mean_nodes);
    EXPECT_EQ(with_curves.frames.back().scenes[m].nodes, without.frames.back().scenes[m].nodes);
  }
}

TEST(WorldFrames, RefuseASuiteWithoutBodiesAndBadRequests) {
  nlohmann::json single = testing::world_suite_json();
  single["scene"].erase("bodies");
  single["feedback"].erase("budget_scope");
  EXPECT_THROW(record_world_frames(parse_suite_text(single.dump(), "one.json"), 0.3, {0}), std::invalid_argument);
  const Suite suite = two_banners();
  EXPECT_THROW(record_world_frames(suite, 1.0, {0}), std::invalid_argument);
  EXPECT_THROW(record_world_frames(suite, 0.3, {10, 5}), std::invalid_argument);
  EXPECT_THROW(record_world_frames(suite, 0.3, {41}), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
