#include "analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace tcsb {
namespace {

void require_finite(std::span<const double> values, const char* who) {
  if (count_nonfinite(values) != 0)
    throw std::invalid_argument(std::string(who) + ": non-finite value (filter diverged data first)");
}

// numpy's two-sided lerp between neighbouring order statistics a <= b at fraction t, so values checked against
// numpy agree to the last bit rather than to a tolerance.
double numpy_lerp(double a, double b, double t) {
  const double diff = b - a;
  return t >= 0.5 ? b - diff * (1.0 - t) : a + diff * t;
}

// Where the p-th percentile of n > 0 sorted values lies: between order statistics lo and lo + 1, at fraction t
// (numpy.percentile(method='linear')).
struct Rank {
  std::size_t lo = 0;
  double t = 0.0;
};

Rank rank_of(std::size_t n, double p) {
  const double index = static_cast<double>(n - 1) * (p / 100.0);
  const double lo_index = std::floor(index);
  return {static_cast<std::size_t>(lo_index), index - lo_index};
}

// Percentile of an already sorted, non-empty sample. Mirrors numpy.percentile(method='linear') exactly.
double sorted_percentile(const std::vector<double>& sorted, double p) {
  const Rank r = rank_of(sorted.size(), p);
  if (r.lo + 1 >= sorted.size()) return sorted.back();
  return numpy_lerp(sorted[r.lo], sorted[r.lo + 1], r.t);
}

void require_percent(double p) {
  if (!(p >= 0.0 && p <= 100.0)) throw std::invalid_argument("percentile: p must be in [0, 100]");
}

std::vector<double> sorted_copy(std::span<const double> values) {
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

}  // namespace

std::size_t count_nonfinite(std::span<const double> values) {
  const auto nonfinite = [](double v) { return !std::isfinite(v); };
  return static_cast<std::size_t>(std::count_if(values.begin(), values.end(), nonfinite));
}

double percentile(std::span<const double> values, double p) {
  require_percent(p);
  require_finite(values, "percentile");
  if (values.empty()) return 0.0;
  // Selection instead of a full sort (O(n): the bootstrap takes medians of ~10^5 operation samples hundreds of
  // times); the same two order statistics and the same lerp as sorted_percentile, so the same bits.
  std::vector<double> v(values.begin(), values.end());
  const Rank r = rank_of(v.size(), p);
  const auto lo = v.begin() + static_cast<std::ptrdiff_t>(r.lo);
  std::nth_element(v.begin(), lo, v.end());
  if (r.lo + 1 >= v.size()) return *lo;
  return numpy_lerp(*lo, *std::min_element(lo + 1, v.end()), r.t);
}

double median(std::span<const double> values) { return percentile(values, 50.0); }

double mean(std::span<const double> values) {
  require_finite(values, "mean");
  if (values.empty()) return 0.0;
  // long double keeps sums of many large timings exact enough and cannot overflow for finite doubles on x86-64.
  long double sum = 0.0L;
  for (const double v : values) sum += v;
  return static_cast<double>(sum / static_cast<long double>(values.size()));
}

Summary summarize(std::span<const double> values) {
  require_finite(values, "summarize");
  Summary s;
  s.count = values.size();
  if (values.empty()) return s;

  const std::vector<double> sorted = sorted_copy(values);
  s.min = sorted.front();
  s.max = sorted.back();
  s.median = sorted_percentile(sorted, 50.0);
  s.p95 = sorted_percentile(sorted, 95.0);
  s.p99 = sorted_percentile(sorted, 99.0);
  s.mean = mean(values);

  if (s.count >= 2) {
    // Two-pass variance around the mean: the one-pass sum-of-squares formula loses everything to cancellation when
    // the spread is tiny relative to the mean, which is exactly the case for repeated timings.
    const long double m = s.mean;
    long double ss = 0.0L;
    for (const double v : values) ss += (v - m) * (v - m);
    s.stddev = static_cast<double>(std::sqrt(ss / static_cast<long double>(s.count - 1)));
    // Only values spanning nearly the whole double range get here; keep the "no non-finite output" promise.
    if (!std::isfinite(s.stddev)) s.stddev = std::numeric_limits<double>::max();
  }
  if (s.mean != 0.0) {
    // |mean| so that a sample of negative values (e.g. signed drift) is judged by its relative spread too.
    s.cv = s.stddev / std::fabs(s.mean);
    // A mean that is nearly zero next to its spread can overflow the ratio; report "huge" rather than infinity.
    if (!std::isfinite(s.cv)) s.cv = std::numeric_limits<double>::max();
  }
  s.unstable = s.cv > kUnstableCv;
  return s;
}

}  // namespace tcsb
