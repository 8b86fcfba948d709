// The non-finite doubles the analysis tests feed to the pure functions, one home for the three test files.
#pragma once

#include <limits>

namespace tcsb::testing {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace tcsb::testing
