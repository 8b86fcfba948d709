#include "analysis/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "non_finite.h"

namespace tcsb {
namespace {

const std::vector<double> kOneToTen{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
using testing::kInf;
using testing::kNaN;

TEST(Percentile, OneToTenMatchesNumpyLinear) {
  // numpy.percentile(range(1, 11), q): index = 9 * q / 100, interpolated between neighbours.
  EXPECT_DOUBLE_EQ(median(kOneToTen), 5.5);
  EXPECT_NEAR(percentile(kOneToTen, 95.0), 9.55, 1e-12);
  EXPECT_NEAR(percentile(kOneToTen, 99.0), 9.91, 1e-12);
  EXPECT_NEAR(percentile(kOneToTen, 25.0), 3.25, 1e-12);
  EXPECT_DOUBLE_EQ(percentile(kOneToTen, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(percentile(kOneToTen, 100.0), 10.0);
}

TEST(Percentile, UnsortedInputGivesSameResult) {
  const std::vector<double> shuffled{7, 3, 10, 1, 9, 2, 8, 5, 4, 6};
  EXPECT_DOUBLE_EQ(percentile(shuffled, 95.0), percentile(kOneToTen, 95.0));
  EXPECT_DOUBLE_EQ(median(shuffled), 5.5);
}

TEST(Percentile, OddCountMedianIsMiddleValue) {
  const std::vector<double> v{9, 1, 5};
  EXPECT_DOUBLE_EQ(median(v), 5.0);
}

TEST(Percentile, EmptyAndSingle) {
  EXPECT_DOUBLE_EQ(percentile({}, 50.0), 0.0);
  const std::vector<double> one{4.25};
  EXPECT_DOUBLE_EQ(percentile(one, 0.0), 4.25);
  EXPECT_DOUBLE_EQ(percentile(one, 99.0), 4.25);
}

TEST(Percentile, RejectsBadPercentAndNonFinite) {
  EXPECT_THROW(percentile(kOneToTen, -0.1), std::invalid_argument);
  EXPECT_THROW(percentile(kOneToTen, 100.1), std::invalid_argument);
  EXPECT_THROW(percentile(kOneToTen, kNaN), std::invalid_argument);
  const std::vector<double> with_nan{1, kNaN, 3};
  EXPECT_THROW(median(with_nan), std::invalid_argument);
  EXPECT_THROW(mean(with_nan), std::invalid_argument);
}

TEST(Mean, Basic) {
  EXPECT_DOUBLE_EQ(mean(kOneToTen), 5.5);
  EXPECT_DOUBLE_EQ(mean({}), 0.0);
}

TEST(Summarize, StddevAndCv) {
  // Deviations from the mean 5 are -3,-1,-1,-1,0,0,2,4: sum of squares 32, sample variance 32/7.
  const std::vector<double> v{2, 4, 4, 4, 5, 5, 7, 9};
  const Summary s = summarize(v);
  EXPECT_EQ(s.count, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.stddev, std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_NEAR(s.cv, std::sqrt(32.0 / 7.0) / 5.0, 1e-12);
  EXPECT_TRUE(s.unstable);  // cv ~ 0.43
  EXPECT_DOUBLE_EQ(s.min, 2.0);
  EXPECT_DOUBLE_EQ(s.max, 9.0);
  EXPECT_DOUBLE_EQ(s.median, 4.5);
}

TEST(Summarize, StableSampleIsNotFlagged) {
  // Mean 100, squares of deviations 0,1,1,0 -> variance 2/3, cv ~ 0.0082.
  const std::vector<double> v{100, 101, 99, 100};
  const Summary s = summarize(v);
  EXPECT_NEAR(s.stddev, std::sqrt(2.0 / 3.0), 1e-12);
  EXPECT_NEAR(s.cv, std::sqrt(2.0 / 3.0) / 100.0, 1e-14);
  EXPECT_FALSE(s.unstable);
}

TEST(Summarize, UnstableThresholdIsStrict) {
  // {9, 10, 11}: mean 10, deviations -1, 0, 1 -> sample variance 2/2 = 1, so cv == 0.10 exactly: not above it.
  const std::vector<double> at{9, 10, 11};
  const Summary s = summarize(at);
  EXPECT_DOUBLE_EQ(s.stddev, 1.0);
  EXPECT_DOUBLE_EQ(s.cv, kUnstableCv);
  EXPECT_FALSE(s.unstable);
  // {8.9, 10, 11.1}: stddev 1.1, cv 0.11 -> unstable.
  const std::vector<double> above{8.9, 10, 11.1};
  EXPECT_NEAR(summarize(above).cv, 0.11, 1e-12);
  EXPECT_TRUE(summarize(above).unstable);
}

TEST(Summarize, PercentilesMatchFreeFunctions) {
  const Summary s = summarize(kOneToTen);
  EXPECT_DOUBLE_EQ(s.median, 5.5);
  EXPECT_DOUBLE_EQ(s.p95, percentile(kOneToTen, 95.0));
  EXPECT_DOUBLE_EQ(s.p99, percentile(kOneToTen, 99.0));
}

TEST(Summarize, SelectionPercentileEqualsTheSortedOneBitForBit) {
  // percentile() selects two order statistics; summarize() sorts. Same bits on awkward data: ties, negatives,
  // many sizes (odd and even), values of very different magnitude.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (std::size_t n = 1; n < 60; ++n) {
    std::vector<double> v;
    for (std::size_t i = 0; i < n; ++i) v.push_back(i % 7 == 3 ? 0.25 : uniform(rng) * (i % 2 ? 1e6 : 1e-3));
    const Summary s = summarize(v);
    EXPECT_EQ(percentile(v, 50.0), s.median) << n;
    EXPECT_EQ(percentile(v, 95.0), s.p95) << n;
    EXPECT_EQ(percentile(v, 99.0), s.p99) << n;
    EXPECT_EQ(percentile(v, 0.0), s.min) << n;
    EXPECT_EQ(percentile(v, 100.0), s.max) << n;
  }
}

TEST(Summarize, SingleValue) {
  const std::vector<double> one{3.5};
  const Summary s = summarize(one);
  EXPECT_EQ(s.count, 1u);
  EXPECT_DOUBLE_EQ(s.median, 3.5);
  EXPECT_DOUBLE_EQ(s.mean, 3.5);
  EXPECT_DOUBLE_EQ(s.p95, 3.5);
  EXPECT_DOUBLE_EQ(s.p99, 3.5);
  EXPECT_DOUBLE_EQ(s.min, 3.5);
  EXPECT_DOUBLE_EQ(s.max, 3.5);
  EXPECT_DOUBLE_EQ(s.stddev, 0.0);
  EXPECT_DOUBLE_EQ(s.cv, 0.0);
  EXPECT_FALSE(s.unstable);
}

TEST(Summarize, EmptyIsAllZeros) {
  const Summary s = summarize({});
  EXPECT_EQ(s.count, 0u);
  EXPECT_DOUBLE_EQ(s.median, 0.0);
  EXPECT_DOUBLE_EQ(s.mean, 0.0);
  EXPECT_DOUBLE_EQ(s.stddev, 0.0);
  EXPECT_DOUBLE_EQ(s.max, 0.0);
  EXPECT_FALSE(s.unstable);
}

TEST(Summarize, ZeroMeanGivesZeroCv) {
  const std::vector<double> v{-1, 1};
  const Summary s = summarize(v);
  EXPECT_DOUBLE_EQ(s.mean, 0.0);
  EXPECT_NEAR(s.stddev, std::sqrt(2.0), 1e-15);
  EXPECT_DOUBLE_EQ(s.cv, 0.0);
  EXPECT_FALSE(std::isnan(s.cv));
}

TEST(Summarize, NegativeMeanGivesPositiveCv) {
  const std::vector<double> v{-9, -11};
  EXPECT_NEAR(summarize(v).cv, std::sqrt(2.0) / 10.0, 1e-15);
}

TEST(Summarize, TinySpreadOnLargeMeanIsNotLost) {
  // A one-pass sum-of-squares formula returns garbage here; the two-pass one gives exactly 1.
  const std::vector<double> v{1e9 + 1, 1e9 + 2, 1e9 + 3};
  EXPECT_NEAR(summarize(v).stddev, 1.0, 1e-9);
}

TEST(Summarize, RejectsNonFinite) {
  const std::vector<double> with_inf{1, kInf};
  const std::vector<double> with_nan{kNaN};
  EXPECT_THROW(summarize(with_inf), std::invalid_argument);
  EXPECT_THROW(summarize(with_nan), std::invalid_argument);
}

TEST(CountNonfinite, CountsNaNAndBothInfinities) {
  const std::vector<double> v{1, kNaN, -kInf, 2, kInf, 0};
  EXPECT_EQ(count_nonfinite(v), 3u);
  EXPECT_EQ(count_nonfinite(kOneToTen), 0u);
  EXPECT_EQ(count_nonfinite({}), 0u);
}

}  // namespace
}  // namespace tcsb
