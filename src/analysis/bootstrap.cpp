#include "analysis/bootstrap.h"

#include <cmath>
#include <stdexcept>

#include "analysis/statistics.h"

namespace tcsb {

std::vector<std::size_t> resample_indices(std::size_t n, std::mt19937_64& rng) {
  std::vector<std::size_t> picks(n);
  for (std::size_t& pick : picks) {
    // Lemire's multiply-shift: maps 64 random bits onto [0, n); the bias (n / 2^64) is far below any use here.
    pick = static_cast<std::size_t>((static_cast<unsigned __int128>(rng()) * n) >> 64);
  }
  return picks;
}

std::vector<double> resample_groups(const std::vector<std::vector<double>>& groups, std::mt19937_64& rng) {
  std::vector<double> pooled;
  for (const std::size_t g : resample_indices(groups.size(), rng)) {
    const std::vector<double>& units = groups[g];
    for (const std::size_t u : resample_indices(units.size(), rng)) pooled.push_back(units[u]);
  }
  return pooled;
}

std::optional<Interval> percentile_interval(std::vector<double> replicates, double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0))
    throw std::invalid_argument("percentile_interval: confidence must lie in (0, 1)");
  std::erase_if(replicates, [](double x) { return !std::isfinite(x); });
  // Below ~20 replicates the tail quantiles are the extreme values themselves: not an interval worth printing.
  if (replicates.size() < 20) return std::nullopt;
  const double tail = 50.0 * (1.0 - confidence);
  return Interval{percentile(replicates, tail), percentile(replicates, 100.0 - tail)};
}

}  // namespace tcsb
