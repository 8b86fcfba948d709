#include "analysis/line_search.h"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace tcsb {

namespace {

/// a better than b: smaller, and any finite value beats a non-finite one.
bool better(double a, double b) {
  if (!std::isfinite(a)) return false;
  return !std::isfinite(b) || a < b;
}

}  // namespace

LineMinimum minimize_on_interval(const std::function<double(double)>& f, double lo, double hi, int scan_points,
                                 double tolerance) {
  if (!(lo < hi) || scan_points < 3 || !(tolerance > 0))
    throw std::invalid_argument("minimize_on_interval: needs lo < hi, at least 3 scan points and a tolerance > 0");
  LineMinimum best;
  best.value = std::nan("");
  const auto eval = [&](double x) {
    const double v = f(x);
    ++best.evaluations;
    if (best.evaluations == 1 || better(v, best.value)) {
      best.x = x;
      best.value = v;
    }
    return v;
  };
  const double step = (hi - lo) / (scan_points - 1);
  int best_index = 0;
  double best_scan = std::nan("");
  for (int i = 0; i < scan_points; ++i) {
    const double v = eval(i == scan_points - 1 ? hi : lo + i * step);
    if (i == 0 || better(v, best_scan)) {
      best_scan = v;
      best_index = i;
    }
  }
  // Golden section between the best scan point's neighbours: the minimum of a function unimodal near it lies there.
  double a = lo + std::max(0, best_index - 1) * step;
  double b = best_index + 1 >= scan_points ? hi : lo + (best_index + 1) * step;
  const double ratio = (std::sqrt(5.0) - 1) / 2;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = eval(c), fd = eval(d);
  while (b - a > tolerance) {
    if (better(fc, fd) || (!std::isfinite(fc) && !std::isfinite(fd))) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = eval(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = eval(d);
    }
  }
  return best;
}

}  // namespace tcsb
