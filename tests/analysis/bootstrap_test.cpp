// The percentile bootstrap's two pieces: drawing resamples and reading an interval off the replicates.
#include "analysis/bootstrap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

namespace tcsb {
namespace {

TEST(Bootstrap, ResamplesDrawInRangeWithReplacementAndRepeatForOneSeed) {
  std::mt19937_64 a(7), b(7);
  std::set<std::size_t> seen;
  bool repeated = false;
  for (int r = 0; r < 200; ++r) {
    const std::vector<std::size_t> picks = resample_indices(7, a);
    ASSERT_EQ(picks.size(), 7u);
    EXPECT_EQ(picks, resample_indices(7, b));  // deterministic for a generator state
    std::set<std::size_t> distinct;
    for (std::size_t p : picks) {
      ASSERT_LT(p, 7u);
      seen.insert(p);
      distinct.insert(p);
    }
    repeated = repeated || distinct.size() < picks.size();
  }
  EXPECT_EQ(seen.size(), 7u);  // every unit gets drawn
  EXPECT_TRUE(repeated);       // with replacement
  EXPECT_TRUE(resample_indices(0, a).empty());
}

TEST(Bootstrap, GroupedResamplesDrawWholeProcessesThenTheirUnits) {
  // Two processes of four repetitions, the processes apart and their repetitions alike. A resample draws a process
  // for each of the two places, then four of that process's repetitions: half the resamples hold one process only
  // (both places drew it), where pooling the eight repetitions would draw one process's units alone in 2 / 2^8.
  const std::vector<int> process_of{1, 1, 1, 1, 2, 2, 2, 2};
  std::mt19937_64 rng(11), again(11);
  int one_process_only = 0;
  for (int r = 0; r < 1000; ++r) {
    const std::vector<std::size_t> drawn = resample_grouped(process_of, rng);
    ASSERT_EQ(drawn.size(), 8u);
    EXPECT_EQ(drawn, resample_grouped(process_of, again));  // deterministic for a generator state
    // Each process's repetitions come as a block: the first four from one process, the last four from one.
    for (std::size_t block : {0u, 4u})
      for (std::size_t i = block; i < block + 4; ++i) ASSERT_EQ(process_of[drawn[i]], process_of[drawn[block]]);
    one_process_only += process_of[drawn.front()] == process_of[drawn.back()];
  }
  EXPECT_GT(one_process_only, 400);
  EXPECT_LT(one_process_only, 600);
}

TEST(Bootstrap, GroupedResamplesOfOneProcessAreExactlyTheUngroupedOnes) {
  // One process (any label): the same generator gives the very indices resample_indices gives, so a run of one
  // process keeps its intervals bit for bit.
  for (const int label : {0, 3}) {
    std::mt19937_64 a(5), b(5);
    for (int r = 0; r < 50; ++r) EXPECT_EQ(resample_grouped(std::vector<int>(6, label), a), resample_indices(6, b));
  }
  std::mt19937_64 rng(3);
  EXPECT_TRUE(resample_grouped({}, rng).empty());
}

TEST(Bootstrap, ProcessesAreCountedByLabel) {
  EXPECT_EQ(process_count({}), 0u);
  EXPECT_EQ(process_count({0, 0, 0}), 1u);
  EXPECT_EQ(process_count({2, 1, 2, 3}), 3u);
}

TEST(Bootstrap, PercentileIntervalIsTheCentralQuantiles) {
  std::vector<double> replicates;
  for (int i = 0; i <= 100; ++i) replicates.push_back(100 - i);  // 100, 99, ..., 0: order must not matter
  const std::optional<Interval> ci = percentile_interval(replicates, 0.95);
  ASSERT_TRUE(ci.has_value());
  EXPECT_NEAR(ci->low, 2.5, 1e-9);  // 50 * (1 - 0.95) is not exactly 2.5 in binary
  EXPECT_NEAR(ci->high, 97.5, 1e-9);
  EXPECT_TRUE(ci->contains(50.0));
  EXPECT_FALSE(ci->contains(1.0));
  const std::optional<Interval> ci90 = percentile_interval(replicates, 0.90);
  ASSERT_TRUE(ci90.has_value());
  EXPECT_NEAR(ci90->low, 5.0, 1e-9);
  EXPECT_NEAR(ci90->high, 95.0, 1e-9);
}

TEST(Bootstrap, UndefinedReplicatesAreDroppedAndTooFewGiveNoInterval) {
  std::vector<double> replicates(30, 1.0);
  replicates.push_back(std::numeric_limits<double>::quiet_NaN());
  replicates.push_back(std::numeric_limits<double>::infinity());
  const std::optional<Interval> ci = percentile_interval(replicates, 0.95);
  ASSERT_TRUE(ci.has_value());
  EXPECT_EQ(ci->low, 1.0);
  EXPECT_EQ(ci->high, 1.0);
  EXPECT_FALSE(percentile_interval(std::vector<double>(19, 1.0), 0.95).has_value());
  EXPECT_FALSE(percentile_interval({}, 0.95).has_value());
}

TEST(Bootstrap, ConfidenceOutsideTheOpenUnitIntervalThrows) {
  EXPECT_THROW(percentile_interval(std::vector<double>(30, 1.0), 0.0), std::invalid_argument);
  EXPECT_THROW(percentile_interval(std::vector<double>(30, 1.0), 1.0), std::invalid_argument);
  EXPECT_THROW(percentile_interval(std::vector<double>(30, 1.0), std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
