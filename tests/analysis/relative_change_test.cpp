#include "analysis/relative_change.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "non_finite.h"

namespace tcsb {
namespace {

using testing::kInf;
using testing::kNaN;

TEST(RelativeChange, Basic) {
  EXPECT_DOUBLE_EQ(relative_change(100.0, 125.0), 0.25);
  EXPECT_DOUBLE_EQ(relative_change(4.0, 2.0), -0.5);
  EXPECT_DOUBLE_EQ(relative_change(3.0, 3.0), 0.0);
  EXPECT_DOUBLE_EQ(relative_change(-2.0, -3.0), 0.5);  // divides by base itself, sign included
}

TEST(RelativeChange, ThrowsInsteadOfReturningNonFinite) {
  EXPECT_THROW(relative_change(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(relative_change(0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(relative_change(kNaN, 1.0), std::invalid_argument);
  EXPECT_THROW(relative_change(1.0, kInf), std::invalid_argument);
  EXPECT_THROW(relative_change(1e-300, 1e300), std::invalid_argument);  // overflows
}

TEST(SafeRatio, Basic) {
  ASSERT_TRUE(safe_ratio(6.0, 3.0).has_value());
  EXPECT_DOUBLE_EQ(*safe_ratio(6.0, 3.0), 2.0);
  EXPECT_DOUBLE_EQ(*safe_ratio(0.0, 3.0), 0.0);
}

TEST(SafeRatio, UndefinedIsNullopt) {
  EXPECT_FALSE(safe_ratio(1.0, 0.0).has_value());
  EXPECT_FALSE(safe_ratio(1.0, -0.0).has_value());
  EXPECT_FALSE(safe_ratio(0.0, 0.0).has_value());
  EXPECT_FALSE(safe_ratio(kNaN, 1.0).has_value());
  EXPECT_FALSE(safe_ratio(1.0, kNaN).has_value());
  EXPECT_FALSE(safe_ratio(kInf, 1.0).has_value());
  EXPECT_FALSE(safe_ratio(1.0, kInf).has_value());
  EXPECT_FALSE(safe_ratio(1e308, 1e-308).has_value());  // overflows to infinity
}

}  // namespace
}  // namespace tcsb
