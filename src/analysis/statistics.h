// Descriptive statistics of a sample of doubles (timings, errors): median, mean, spread and tail percentiles.
// All functions require finite inputs and throw std::invalid_argument otherwise, so a NaN can never leak into a
// result file: callers filter diverged runs first (count_nonfinite tells how many they dropped).
#pragma once

#include <cstddef>
#include <span>

namespace tcsb {

/// Coefficient of variation above which a sample is flagged unstable (the design's 10 % threshold).
inline constexpr double kUnstableCv = 0.10;

/// Summary of a sample of finite doubles; all zeros (count 0) for an empty sample.
struct Summary {
  std::size_t count = 0;  ///< number of values
  double median = 0.0;    ///< 50th percentile
  double mean = 0.0;      ///< arithmetic mean
  double stddev = 0.0;    ///< sample standard deviation (n-1 denominator); 0 for n < 2
  double cv = 0.0;        ///< stddev / |mean|; 0 when mean == 0
  double p95 = 0.0;       ///< 95th percentile (linear interpolation)
  double p99 = 0.0;       ///< 99th percentile (linear interpolation)
  double min = 0.0;       ///< smallest value
  double max = 0.0;       ///< largest value
  bool unstable = false;  ///< cv > kUnstableCv
};

/// Summarises `values` (any order). Throws std::invalid_argument if any value is non-finite.
Summary summarize(std::span<const double> values);

/// The p-th percentile, p in [0, 100], by linear interpolation between order statistics (numpy's default
/// 'linear' method); `values` need not be sorted; 0 for an empty sample. Throws std::invalid_argument on p outside
/// [0, 100] or a non-finite value.
double percentile(std::span<const double> values, double p);

/// The median (50th percentile, mean of the two middle values for even counts); 0 for an empty sample.
double median(std::span<const double> values);

/// The arithmetic mean, accumulated in long double; 0 for an empty sample. Throws on a non-finite value.
double mean(std::span<const double> values);

/// Number of NaN or infinite values: what a caller must filter out (and report) before summarising.
std::size_t count_nonfinite(std::span<const double> values);

}  // namespace tcsb
