// Verdicts from seeded synthetic measurements: the bootstrap interval of a mean, judged at the looks' levels. A
// claim whose truth is far from its threshold is decided at once; one exactly at its threshold stays undecided;
// one near its threshold is decided once more repetitions narrow its interval.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analysis/bootstrap.h"
#include "analysis/claim.h"
#include "analysis/sequential_looks.h"
#include "analysis/statistics.h"

namespace tcsb {
namespace {

/// n seeded draws around `mean` (uniform in mean +- spread: bounded, so no seed can produce a wild outlier).
std::vector<double> draws(double mean, double spread, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> x;
  for (std::size_t i = 0; i < n; ++i)
    x.push_back(mean + spread * (2.0 * static_cast<double>(rng() >> 11) / 9007199254740992.0 - 1.0));
  return x;
}

/// The claim "mean at most 1.0" judged on `samples` at look `look`.
Claim judged_at(const std::vector<double>& samples, int look) {
  std::mt19937_64 rng(7);
  std::vector<double> replicates;
  for (int b = 0; b < look_resamples(kSequentialAlpha, look); ++b) {
    std::vector<double> resample;
    for (const std::size_t i : resample_indices(samples.size(), rng)) resample.push_back(samples[i]);
    replicates.push_back(mean(resample));
  }
  Claim c = check_claim("mean", "", Comparison::kAtMost, 1.0, 0.0, mean(samples), Evidence::kRepeated);
  c.interval = percentile_interval(replicates, look_confidence(kSequentialAlpha, look));
  return c;
}

TEST(Verdict, ATruePassIsDecidedAtTheFirstLook) {
  EXPECT_EQ(verdict(judged_at(draws(0.8, 0.05, 5, 1), 1)), Verdict::kPass);
}

TEST(Verdict, ATrueFailIsDecidedAtTheFirstLook) {
  EXPECT_EQ(verdict(judged_at(draws(1.2, 0.05, 5, 2), 1)), Verdict::kFail);
}

TEST(Verdict, AMeasurementAtTheThresholdIsUndecidedAtEveryLook) {
  // Symmetric about 1.0: every resample's mean lies on both sides often, at any number of repetitions.
  std::vector<double> at_threshold;
  for (int i = 0; i < 40; ++i) at_threshold.push_back(i % 2 == 0 ? 0.9 : 1.1);
  for (int look = 1; look <= 5; ++look)
    EXPECT_EQ(verdict(judged_at(at_threshold, look)), Verdict::kUndecided) << "look " << look;
}

TEST(Verdict, ANearMeasurementIsDecidedAfterMoreRepetitions) {
  // True mean 0.9 with +-0.3 noise: 5 repetitions cannot tell it from 1.0; 80 can, even at look 3's 98.75 %.
  const std::vector<double> first{0.6, 1.2, 0.8, 1.1, 0.9};  // the run's own five: mean 0.92, wide
  EXPECT_EQ(verdict(judged_at(first, 1)), Verdict::kUndecided);
  std::vector<double> all = first;
  for (const double x : draws(0.9, 0.3, 75, 3)) all.push_back(x);
  EXPECT_EQ(verdict(judged_at(all, 3)), Verdict::kPass);
}

TEST(SequentialLooks, EachLookSpendsHalfTheRestAndAllStayBelowAlpha) {
  EXPECT_DOUBLE_EQ(look_alpha(0.05, 1), 0.025);
  EXPECT_DOUBLE_EQ(look_alpha(0.05, 2), 0.0125);
  EXPECT_DOUBLE_EQ(look_confidence(0.05, 1), 0.95);  // the first look is the familiar 95 % interval
  EXPECT_DOUBLE_EQ(look_confidence(0.05, 3), 0.9875);
  double spent = 0;
  for (int k = 1; k <= 30; ++k) spent += look_alpha(0.05, k);
  EXPECT_LT(spent, 0.05);
  EXPECT_THROW(look_alpha(0.05, 0), std::invalid_argument);
  EXPECT_THROW(look_alpha(1.5, 1), std::invalid_argument);
}

TEST(SequentialLooks, ResamplesLeaveTenReplicatesInEachTail) {
  EXPECT_EQ(look_resamples(0.05, 1), 400);
  EXPECT_EQ(look_resamples(0.05, 2), 800);
  EXPECT_EQ(look_resamples(0.05, 5), 6400);
  for (int k = 1; k <= 6; ++k)
    EXPECT_GE(look_resamples(0.05, k) * look_alpha(0.05, k), kReplicatesPerTail - 1e-9) << "look " << k;
}

}  // namespace
}  // namespace tcsb
