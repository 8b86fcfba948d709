#include "analysis/bootstrap.h"

#include <algorithm>
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

namespace {

/// The units of each process, processes in the order they first appear.
std::vector<std::vector<std::size_t>> units_by_process(const std::vector<int>& process_of) {
  std::vector<int> labels;
  std::vector<std::vector<std::size_t>> units;
  for (std::size_t u = 0; u < process_of.size(); ++u) {
    const auto it = std::find(labels.begin(), labels.end(), process_of[u]);
    if (it == labels.end()) {
      labels.push_back(process_of[u]);
      units.push_back({u});
    } else {
      units[static_cast<std::size_t>(it - labels.begin())].push_back(u);
    }
  }
  return units;
}

}  // namespace

std::vector<std::size_t> resample_grouped(const std::vector<int>& process_of, std::mt19937_64& rng) {
  const std::vector<std::vector<std::size_t>> units = units_by_process(process_of);
  if (units.size() <= 1) return resample_indices(process_of.size(), rng);
  std::vector<std::size_t> picks;
  picks.reserve(process_of.size());
  for (const std::size_t p : resample_indices(units.size(), rng)) {
    const std::vector<std::size_t>& of_process = units[p];
    for (const std::size_t u : resample_indices(of_process.size(), rng)) picks.push_back(of_process[u]);
  }
  return picks;
}

std::size_t process_count(const std::vector<int>& process_of) { return units_by_process(process_of).size(); }

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
