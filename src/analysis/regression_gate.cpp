#include "analysis/regression_gate.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "analysis/mann_whitney.h"
#include "analysis/relative_change.h"
#include "analysis/statistics.h"

namespace tcsb {

std::vector<double> holm_adjust(std::span<const double> p_values) {
  for (const double p : p_values) {
    if (!(p >= 0.0 && p <= 1.0)) throw std::invalid_argument("holm_adjust: p-value outside [0, 1]");
  }
  const std::size_t m = p_values.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Stable, so equal p-values keep input order and the result does not depend on the sort implementation.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p_values[a] < p_values[b]; });
  std::vector<double> adjusted(m);
  double running = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    running = std::max(running, std::min(1.0, p_values[order[i]] * static_cast<double>(m - i)));
    adjusted[order[i]] = running;
  }
  return adjusted;
}

std::vector<TimingDecision> decide_timings(std::span<const TimingSamples> family, const GateSettings& settings) {
  if (!(settings.alpha > 0.0 && settings.alpha < 1.0)) {
    throw std::invalid_argument("decide_timings: alpha outside (0, 1)");
  }
  if (!(settings.threshold >= 0.0) || !std::isfinite(settings.threshold)) {
    throw std::invalid_argument("decide_timings: threshold must be a finite number >= 0");
  }
  std::vector<TimingDecision> decisions(family.size());
  // One-sided p-values of the reliable metrics, in both directions; Holm runs over each direction's family.
  std::vector<std::size_t> reliable;
  std::vector<double> p_larger, p_smaller;
  for (std::size_t i = 0; i < family.size(); ++i) {
    const TimingSamples& s = family[i];
    TimingDecision& d = decisions[i];
    d.base_count = s.base.size();
    d.next_count = s.next.size();
    if (count_nonfinite(s.base) > 0 || count_nonfinite(s.next) > 0) {
      throw std::invalid_argument("decide_timings: non-finite sample value");
    }
    if (!s.base.empty()) d.base_median = median(s.base);
    if (!s.next.empty()) d.next_median = median(s.next);
    if (d.base_median && d.next_median) d.change = safe_ratio(*d.next_median - *d.base_median, *d.base_median);
    if (!d.change || d.base_count < settings.min_samples || d.next_count < settings.min_samples) continue;
    reliable.push_back(i);
    p_larger.push_back(mann_whitney_u(s.next, s.base, Alternative::kGreater).p_value);
    p_smaller.push_back(mann_whitney_u(s.next, s.base, Alternative::kLess).p_value);
  }
  const std::vector<double> adj_larger = holm_adjust(p_larger);
  const std::vector<double> adj_smaller = holm_adjust(p_smaller);
  for (std::size_t k = 0; k < reliable.size(); ++k) {
    TimingDecision& d = decisions[reliable[k]];
    const bool larger = *d.change >= 0.0;
    d.p_value = larger ? adj_larger[k] : adj_smaller[k];
    const bool significant = *d.p_value <= settings.alpha;
    if (significant && larger && *d.change > settings.threshold)
      d.verdict = TimingVerdict::kRegressed;
    else if (significant && !larger && -*d.change > settings.threshold)
      d.verdict = TimingVerdict::kImproved;
    else
      d.verdict = TimingVerdict::kUnchanged;
  }
  return decisions;
}

const char* verdict_name(TimingVerdict verdict) {
  switch (verdict) {
    case TimingVerdict::kUnchanged: return "unchanged";
    case TimingVerdict::kRegressed: return "regressed";
    case TimingVerdict::kImproved: return "improved";
    case TimingVerdict::kUnreliable: return "unreliable";
  }
  return "unreliable";
}

}  // namespace tcsb
