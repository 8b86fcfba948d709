// One-dimensional minimisation on an interval: a uniform scan to find the basin (the function need not be unimodal
// over the whole interval), then golden-section search inside the scan's best bracket. Pure; the function is any
// callable, so it can be a whole simulation (the calibration's link stiffness fit).
#pragma once

#include <functional>

namespace tcsb {

/// Where the search ended.
struct LineMinimum {
  double x = 0;         ///< the best argument evaluated
  double value = 0;     ///< f(x)
  int evaluations = 0;  ///< calls of f
};

/// Minimises f on [lo, hi]: f at `scan_points` (>= 3) evenly spaced points, both ends included, then golden-section
/// search between the best scan point's neighbours until the bracket is narrower than `tolerance`. Returns the best
/// point evaluated (a non-finite value counts as worse than any finite one). Throws std::invalid_argument on
/// lo >= hi, fewer than 3 scan points or a tolerance <= 0.
LineMinimum minimize_on_interval(const std::function<double(double)>& f, double lo, double hi, int scan_points,
                                 double tolerance);

}  // namespace tcsb
