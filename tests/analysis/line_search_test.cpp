#include "analysis/line_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tcsb {
namespace {

TEST(LineSearch, FindsTheMinimumOfAParabolaWithinTheTolerance) {
  const LineMinimum m = minimize_on_interval([](double x) { return (x - 0.37) * (x - 0.37) + 2; }, 0.02, 1.0, 7, 1e-3);
  EXPECT_NEAR(m.x, 0.37, 1e-3);
  EXPECT_NEAR(m.value, 2.0, 1e-6);
  EXPECT_GT(m.evaluations, 7);
  EXPECT_LT(m.evaluations, 30);
}

TEST(LineSearch, TheScanFindsTheDeeperOfTwoBasinsAndAnEndpointMinimum) {
  // Two basins: golden section alone from the whole interval could settle in the shallow one at 0.8.
  const auto two = [](double x) { return std::min(std::abs(x - 0.2) + 0.1, std::abs(x - 0.8)); };
  EXPECT_NEAR(minimize_on_interval(two, 0.0, 1.0, 11, 1e-4).x, 0.8, 1e-3);
  EXPECT_NEAR(minimize_on_interval([](double x) { return x; }, 0.1, 1.0, 5, 1e-4).x, 0.1, 1e-12);
}

TEST(LineSearch, NonFiniteValuesLoseToFiniteOnes) {
  // A diverged simulation (NaN, infinity) must never be chosen.
  const auto f = [](double x) { return x < 0.5 ? std::numeric_limits<double>::quiet_NaN() : x; };
  const LineMinimum m = minimize_on_interval(f, 0.0, 1.0, 5, 1e-4);
  EXPECT_TRUE(std::isfinite(m.value));
  EXPECT_NEAR(m.x, 0.5, 1e-3);
}

TEST(LineSearch, RefusesABadInterval) {
  const auto f = [](double x) { return x; };
  EXPECT_THROW(minimize_on_interval(f, 1.0, 1.0, 5, 1e-3), std::invalid_argument);
  EXPECT_THROW(minimize_on_interval(f, 0.0, 1.0, 2, 1e-3), std::invalid_argument);
  EXPECT_THROW(minimize_on_interval(f, 0.0, 1.0, 5, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
