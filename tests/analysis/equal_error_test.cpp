// Time at equal error: log-log interpolation on a rival's curve, never extrapolated, the first crossing on a curve
// that is not monotone.
#include "analysis/equal_error.h"

#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>

namespace tcsb {
namespace {

TEST(EqualError, InterpolatesInLogLogBetweenThePointsAroundTheError) {
  // time = 100 / error on this curve, a straight line in log-log: at error 50 the time is exactly 2.
  const std::vector<CurvePoint> curve{{4.0, 25.0}, {1.0, 100.0}};  // any order: sorted by time
  const TimeAtError at = time_at_error(curve, 50.0);
  EXPECT_EQ(at.status, EqualErrorStatus::kInterpolated);
  EXPECT_NEAR(at.time_ms, 2.0, 1e-12);
  // On a point, its own time.
  EXPECT_NEAR(time_at_error(curve, 25.0).time_ms, 4.0, 1e-12);
}

TEST(EqualError, NeverExtrapolates) {
  const std::vector<CurvePoint> curve{{1.0, 100.0}, {4.0, 25.0}};
  // More accurate than the curve's finest point: not reached, no time.
  const TimeAtError finer = time_at_error(curve, 10.0);
  EXPECT_EQ(finer.status, EqualErrorStatus::kNotReached);
  EXPECT_EQ(finer.time_ms, 0.0);
  // Less accurate than its cheapest point: the cheapest time is a bound, not a value below it.
  const TimeAtError coarser = time_at_error(curve, 200.0);
  EXPECT_EQ(coarser.status, EqualErrorStatus::kAtCheapest);
  EXPECT_EQ(coarser.time_ms, 1.0);
  EXPECT_STREQ(equal_error_status_name(coarser.status), "at_cheapest");
}

TEST(EqualError, ANonMonotoneCurveIsReadAtItsFirstCrossingAndSaysSo) {
  // The error dips below 20 at time 2, rises, and falls again: the cheapest way to 20 is the first crossing.
  const std::vector<CurvePoint> curve{{1.0, 40.0}, {2.0, 10.0}, {3.0, 30.0}, {4.0, 5.0}};
  EXPECT_FALSE(is_monotone(curve));
  const TimeAtError at = time_at_error(curve, 20.0);
  EXPECT_EQ(at.status, EqualErrorStatus::kInterpolated);
  EXPECT_GT(at.time_ms, 1.0);
  EXPECT_LT(at.time_ms, 2.0);
  EXPECT_TRUE(is_monotone({{1.0, 40.0}, {2.0, 40.0}, {3.0, 5.0}}));
}

TEST(EqualError, RefusesWhatALogCannotTake) {
  EXPECT_THROW(time_at_error({}, 1.0), std::invalid_argument);
  EXPECT_THROW(time_at_error({{1.0, 0.0}}, 1.0), std::invalid_argument);
  EXPECT_THROW(time_at_error({{0.0, 1.0}}, 1.0), std::invalid_argument);
  EXPECT_THROW(time_at_error({{1.0, 1.0}}, 0.0), std::invalid_argument);
}

TEST(ErrorAtNodes, InterpolatesInLogLogBetweenTheCountsAroundIt) {
  // error = 1000 / nodes, a straight line in log-log: at 200 nodes exactly 5 (linear in nodes would give 6.25).
  const std::vector<NodesPoint> curve{{400.0, 2.5}, {100.0, 10.0}};  // any order: sorted by nodes
  const std::optional<double> at = error_at_nodes(curve, 200.0);
  ASSERT_TRUE(at);
  EXPECT_NEAR(*at, 5.0, 1e-12);
  EXPECT_EQ(error_at_nodes(curve, 400.0), 2.5);  // on a point, its own error
  EXPECT_EQ(error_at_nodes(curve, 100.0), 10.0);
}

TEST(ErrorAtNodes, NeverExtrapolatesAndReadsEachSegmentOnItsOwn) {
  const std::vector<NodesPoint> curve{{100.0, 10.0}, {200.0, 4.0}, {400.0, 3.0}};
  EXPECT_FALSE(error_at_nodes(curve, 99.0));
  EXPECT_FALSE(error_at_nodes(curve, 401.0));
  const std::optional<double> upper = error_at_nodes(curve, 300.0);  // between the second and the third point only
  ASSERT_TRUE(upper);
  EXPECT_GT(*upper, 3.0);
  EXPECT_LT(*upper, 4.0);
}

TEST(ErrorAtNodes, RefusesWhatALogCannotTake) {
  EXPECT_THROW(error_at_nodes({}, 1.0), std::invalid_argument);
  EXPECT_THROW(error_at_nodes({{1.0, 0.0}}, 1.0), std::invalid_argument);
  EXPECT_THROW(error_at_nodes({{0.0, 1.0}}, 1.0), std::invalid_argument);
  EXPECT_THROW(error_at_nodes({{1.0, 1.0}}, 0.0), std::invalid_argument);
  EXPECT_THROW(error_at_nodes({{1.0, 1.0}, {1.0, 2.0}}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
