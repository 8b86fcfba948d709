// Ordinary least-squares fit of a straight line y = a + b*x, with R² and residuals: used to show that cost grows
// linearly with problem size (and to report the per-unit slope).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace tcsb {

/// Result of fit_linear; every number is finite, and meaningful only when `valid`.
struct LinearFit {
  bool valid = false;             ///< false if fewer than 2 points or all x equal (slope undefined)
  double intercept = 0.0;         ///< a in y = a + b*x
  double slope = 0.0;             ///< b in y = a + b*x
  double r2 = 0.0;                ///< 1 - SS_res/SS_tot; 1 when all y are equal (a line fits them exactly)
  std::vector<double> residuals;  ///< y_i - (a + b*x_i), in input order (empty when not valid)
  std::size_t points = 0;         ///< number of (x, y) pairs given
};

/// Least-squares line through (x_i, y_i). Throws std::invalid_argument if the sizes differ or a value is
/// non-finite (callers filter diverged runs first).
LinearFit fit_linear(std::span<const double> x, std::span<const double> y);

}  // namespace tcsb
