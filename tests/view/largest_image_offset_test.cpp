// LargestImageOffset: the longest offset, bit for bit what std::max over every std::hypot gives, though it measures
// only the offsets near the longest: over random offsets, offsets a unit in the last place apart, offsets near the
// underflow, lengths given as they are and undefined ones.
#include "view/largest_image_offset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace tcsb {
namespace {

/// What the coarse-jump charge took before: std::max over every offset's hypot and every length, from 0.
double longest_by_every_hypot(const std::vector<Eigen::Vector2d>& offsets, const std::vector<double>& lengths) {
  double longest = 0;
  for (const Eigen::Vector2d& o : offsets) longest = std::max(longest, std::hypot(o.x(), o.y()));
  for (const double l : lengths) longest = std::max(longest, l);
  return longest;
}

double longest_measured(const std::vector<Eigen::Vector2d>& offsets, const std::vector<double>& lengths) {
  LargestImageOffset largest;
  for (const Eigen::Vector2d& o : offsets) largest.add(o);
  for (const double l : lengths) largest.add_length(l);
  return largest.length();
}

TEST(LargestImageOffset, NothingAddedIsNoLength) { EXPECT_EQ(LargestImageOffset().length(), 0.0); }

TEST(LargestImageOffset, IsTheLargestHypotToTheLastBit) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-50, 50), scale_exponent(-320, 20);
  std::uniform_int_distribution<int> count(1, LargestImageOffset::kCapacity), kind(0, 3);
  int near_ties = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::pow(10.0, scale_exponent(random));  // down to subnormal squares
    std::vector<Eigen::Vector2d> offsets;
    const int n = count(random);
    for (int k = 0; k < n; ++k) {
      Eigen::Vector2d o(coordinate(random) * scale, coordinate(random) * scale);
      if (k > 0 && kind(random) == 0) {  // a unit in the last place from an earlier one, or the same turned
        const Eigen::Vector2d& e = offsets[static_cast<std::size_t>(random() % offsets.size())];
        o = random() % 2 == 0 ? Eigen::Vector2d(std::nextafter(e.x(), 1e300), e.y()) : Eigen::Vector2d(e.y(), -e.x());
        ++near_ties;
      }
      offsets.push_back(o);
    }
    std::vector<double> lengths;
    if (kind(random) == 0) lengths.push_back(std::abs(coordinate(random)) * scale);
    const double expected = longest_by_every_hypot(offsets, lengths);
    ASSERT_EQ(longest_measured(offsets, lengths), expected) << "trial " << trial;
  }
  EXPECT_GT(near_ties, 10000);
}

TEST(LargestImageOffset, InfiniteAndUndefinedOffsetsAreMeasuredAsTheyAre) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<Eigen::Vector2d>> cases = {
      {{3, 4}, {nan, 1}},  // undefined: passed over
      {{3, 4}, {inf, 1}},
      {{3, 4}, {inf, nan}},      // hypot(inf, NaN) is inf
      {{1e200, 1e200}, {2, 2}},  // a square that overflows: measured as it is
  };
  for (const auto& offsets : cases) {
    const double expected = longest_by_every_hypot(offsets, {});
    EXPECT_EQ(longest_measured(offsets, {}), expected) << offsets.front().x();
  }
  EXPECT_EQ(longest_measured({{3, 4}}, {nan}), 5.0);
}

}  // namespace
}  // namespace tcsb
