#include "fidelity/discrete_lod.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tcsb {

int DiscreteLod::level(double distance) const {
  int k = 0;
  while (k + 1 < levels && distance > scale * std::ldexp(1.0, k)) ++k;
  return k;
}

int DiscreteLod::level(double distance, int current) const {
  const int plain = level(distance);
  if (plain > current) {
    // Coarser only beyond the margin past the threshold crossed first (current's outer one).
    const double outer = scale * std::ldexp(1.0, current) * (1 + hysteresis);
    return distance > outer ? plain : current;
  }
  if (plain < current) {
    const double inner = scale * std::ldexp(1.0, current - 1) * (1 - hysteresis);
    return distance < inner ? plain : current;
  }
  return current;
}

std::vector<int> lod_schedule(const DiscreteLod& lod, std::span<const double> distances, std::size_t bodies) {
  std::vector<int> levels(distances.size());
  for (std::size_t i = 0; i < distances.size(); ++i)
    levels[i] = i < bodies ? lod.level(distances[i]) : lod.level(distances[i], levels[i - bodies]);
  return levels;
}

double mean_lod_nodes(std::span<const int> levels, std::span<const int> level_nodes, std::size_t bodies) {
  if (levels.empty() || bodies == 0) return 0;
  double total = 0;
  for (const int k : levels) total += level_nodes[static_cast<std::size_t>(k)];
  return total / static_cast<double>(levels.size() / bodies);
}

DiscreteLod fit_discrete_lod(std::span<const int> level_nodes, std::span<const double> distances, std::size_t bodies,
                             double budget, double hysteresis) {
  if (level_nodes.empty()) throw std::invalid_argument("fit_discrete_lod: no levels");
  if (bodies == 0 || distances.size() % bodies != 0)
    throw std::invalid_argument("fit_discrete_lod: the distances are not a whole number of steps");
  if (!(hysteresis >= 0 && hysteresis < 1)) throw std::invalid_argument("fit_discrete_lod: hysteresis not in [0, 1)");
  DiscreteLod lod;
  lod.levels = static_cast<int>(level_nodes.size());
  lod.hysteresis = hysteresis;
  const auto mean_at = [&](double scale) {
    lod.scale = scale;
    return mean_lod_nodes(lod_schedule(lod, distances, bodies), level_nodes, bodies);
  };
  // At scale 0 every body is coarsest; at a scale beyond every distance, finest.
  double far = 1;
  for (const double d : distances) far = std::max(far, d);
  double lo = 0, hi = 2 * far / (1 - hysteresis);
  if (mean_at(lo) > budget || mean_at(hi) <= budget) return lod;  // coarsest everywhere, or finest: it fits
  while (hi - lo > 1e-9 * hi) {
    const double mid = 0.5 * (lo + hi);
    (mean_at(mid) <= budget ? lo : hi) = mid;
  }
  lod.scale = lo;
  return lod;
}

}  // namespace tcsb
