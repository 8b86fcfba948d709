// Discrete levels of detail: levels by distance, the margin against flicker, and the thresholds that meet a budget.
#include "fidelity/discrete_lod.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace tcsb {
namespace {

TEST(DiscreteLod, EachLevelTwiceAsFarAsTheLast) {
  const DiscreteLod lod{10.0, 0.1, 3};
  EXPECT_EQ(lod.level(5), 0);
  EXPECT_EQ(lod.level(10), 0);  // at the threshold: still the finer
  EXPECT_EQ(lod.level(15), 1);
  EXPECT_EQ(lod.level(25), 2);
  EXPECT_EQ(lod.level(1000), 2);  // no coarser grid than the last
}

TEST(DiscreteLod, TheMarginKeepsABodyNearAThresholdFromFlickering) {
  const DiscreteLod lod{10.0, 0.1, 3};
  EXPECT_EQ(lod.level(10.5, 0), 0);  // past 10 m but inside 11: keeps level 0
  EXPECT_EQ(lod.level(11.5, 0), 1);
  EXPECT_EQ(lod.level(9.5, 1), 1);  // back inside 10 m but not 9: keeps level 1
  EXPECT_EQ(lod.level(8.5, 1), 0);
  EXPECT_EQ(lod.level(50, 0), 2);  // far past both: straight to the coarsest
  EXPECT_EQ(lod.level(1, 2), 0);
}

TEST(DiscreteLod, AScheduleFollowsEachBodyWithItsHistory) {
  const DiscreteLod lod{10.0, 0.1, 2};
  // Two bodies over four steps: the first goes out past 10 m and comes back; the second stays at 30 m.
  const std::vector<double> d{9, 30, 10.5, 30, 11.5, 30, 9.5, 30};
  EXPECT_EQ(lod_schedule(lod, d, 2), (std::vector<int>{0, 1, 0, 1, 1, 1, 1, 1}));
  const std::vector<int> nodes{100, 25};
  EXPECT_DOUBLE_EQ(mean_lod_nodes(lod_schedule(lod, d, 2), nodes, 2), (125 + 125 + 50 + 50) / 4.0);
}

TEST(DiscreteLod, FitsTheLargestMeanNodeCountWithinTheBudget) {
  // Three bodies at 5, 20 and 80 m for two steps, then 40, 20 and 10 m for two.
  const std::vector<double> d{5, 20, 80, 5, 20, 80, 40, 20, 10, 40, 20, 10};
  const std::vector<int> nodes{289, 81, 25};
  for (const double budget : {100.0, 200.0, 400.0, 700.0}) {
    const DiscreteLod lod = fit_discrete_lod(nodes, d, 3, budget, 0.1);
    const double mean = mean_lod_nodes(lod_schedule(lod, d, 3), nodes, 3);
    EXPECT_LE(mean, budget) << budget;
    DiscreteLod finer = lod;
    finer.scale *= 1 + 1e-6;  // any larger scale no longer fits
    EXPECT_GT(mean_lod_nodes(lod_schedule(finer, d, 3), nodes, 3), budget) << budget;
  }
  // Coarsest everywhere (75 nodes) already over 50; finest everywhere (867) within 1000.
  EXPECT_EQ(fit_discrete_lod(nodes, d, 3, 50, 0.1).scale, 0.0);
  const DiscreteLod all = fit_discrete_lod(nodes, d, 3, 1000, 0.1);
  EXPECT_DOUBLE_EQ(mean_lod_nodes(lod_schedule(all, d, 3), nodes, 3), 867.0);
}

TEST(DiscreteLod, RefusesWhatHasNoAnswer) {
  const std::vector<double> d{1, 2, 3};
  const std::vector<int> nodes{9, 4};
  EXPECT_THROW(fit_discrete_lod({}, d, 1, 10, 0.1), std::invalid_argument);
  EXPECT_THROW(fit_discrete_lod(nodes, d, 2, 10, 0.1), std::invalid_argument);  // 3 distances, 2 bodies
  EXPECT_THROW(fit_discrete_lod(nodes, d, 1, 10, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
