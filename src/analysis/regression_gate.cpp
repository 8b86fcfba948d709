#include "analysis/regression_gate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

#include "analysis/claim.h"
#include "analysis/mann_whitney.h"
#include "analysis/relative_change.h"
#include "analysis/sequential_looks.h"
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

namespace {

/// A side's processes: as given, or one process for every sample.
std::vector<int> processes_of(const std::vector<int>& process, std::size_t samples) {
  return process.empty() ? std::vector<int>(samples, 0) : process;
}

/// The values at `picks`, in order.
std::vector<double> picked(const std::vector<double>& values, const std::vector<std::size_t>& picks) {
  std::vector<double> out;
  out.reserve(picks.size());
  for (const std::size_t i : picks) out.push_back(values[i]);
  return out;
}

/// The percentile bootstrap interval of the median's relative change, each side resampled on its own: its
/// processes, then their samples (with one process, the samples alone).
std::optional<Interval> change_interval(const TimingSamples& s, double one_sided_alpha, std::uint64_t seed) {
  // Each tail rests on kReplicatesPerTail replicates, as reproduce's intervals do (analysis/sequential_looks.h).
  const auto resamples = static_cast<std::size_t>(std::ceil(kReplicatesPerTail / one_sided_alpha - 1e-9));
  std::mt19937_64 rng(seed);
  const std::vector<int> base_process = processes_of(s.base_process, s.base.size());
  const std::vector<int> next_process = processes_of(s.next_process, s.next.size());
  std::vector<double> replicates;
  replicates.reserve(resamples);
  for (std::size_t r = 0; r < resamples; ++r) {
    const std::vector<double> base = picked(s.base, resample_grouped(base_process, rng));
    const std::vector<double> next = picked(s.next, resample_grouped(next_process, rng));
    const double mb = median(base);
    const std::optional<double> change = safe_ratio(median(next) - mb, mb);
    replicates.push_back(change ? *change : std::numeric_limits<double>::quiet_NaN());
  }
  return percentile_interval(std::move(replicates), 1.0 - 2.0 * one_sided_alpha);
}

/// The three verdicts of a claim "the change is at most the threshold" judged on its interval (analysis/claim.h):
/// pass is no regression (or an improvement beyond the threshold), fail a regression.
TimingVerdict interval_verdict(double change, const Interval& interval, double threshold) {
  Claim claim = check_claim("no_regression", "", Comparison::kAtMost, threshold, 0.0, change, Evidence::kRepeated);
  claim.interval = interval;
  switch (verdict(claim)) {
    case Verdict::kFail: return TimingVerdict::kRegressed;
    case Verdict::kUndecided: return TimingVerdict::kUndecided;
    case Verdict::kPass: break;
  }
  return interval.high < -threshold ? TimingVerdict::kImproved : TimingVerdict::kUnchanged;
}

}  // namespace

std::optional<int> repetitions_to_decide(double change, const Interval& interval, double threshold, std::size_t n) {
  // The end facing the threshold, and how far it must come in: it has to pass the threshold.
  const double reach = change < threshold ? interval.high - change : change - interval.low;
  const double room = std::abs(threshold - change);
  if (!(room > 0.0) || !(reach > room) || n == 0) return std::nullopt;
  const double needed = static_cast<double>(n) * (reach / room) * (reach / room);  // reach * sqrt(n / N) = room
  const double extra = std::ceil(needed - static_cast<double>(n));
  return static_cast<int>(std::clamp(extra, 1.0, static_cast<double>(kMaxMoreRepetitions)));
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
    if ((!s.base_process.empty() && s.base_process.size() != s.base.size()) ||
        (!s.next_process.empty() && s.next_process.size() != s.next.size())) {
      throw std::invalid_argument("decide_timings: a process list of another length than its samples");
    }
    d.base_processes = std::max<std::size_t>(1, process_count(s.base_process));
    d.next_processes = std::max<std::size_t>(1, process_count(s.next_process));
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
  const double one_sided_alpha = settings.alpha / static_cast<double>(std::max<std::size_t>(reliable.size(), 1));
  for (std::size_t k = 0; k < reliable.size(); ++k) {
    TimingDecision& d = decisions[reliable[k]];
    const bool larger = *d.change >= 0.0;
    d.p_value = larger ? adj_larger[k] : adj_smaller[k];
    // One seed per metric, derived from its place in the family: the same files give the same verdicts.
    d.interval = change_interval(family[reliable[k]], one_sided_alpha, settings.seed + reliable[k]);
    if (!d.interval) {
      d.verdict = TimingVerdict::kUnreliable;  // the change is undefined on too many resamples (a zero median)
      continue;
    }
    d.confidence = 1.0 - 2.0 * one_sided_alpha;
    d.verdict = interval_verdict(*d.change, *d.interval, settings.threshold);
    if (d.verdict == TimingVerdict::kUndecided)
      d.more_repetitions =
          repetitions_to_decide(*d.change, *d.interval, settings.threshold, std::min(d.base_count, d.next_count));
  }
  return decisions;
}

const char* verdict_name(TimingVerdict verdict) {
  switch (verdict) {
    case TimingVerdict::kUnchanged: return "unchanged";
    case TimingVerdict::kRegressed: return "regressed";
    case TimingVerdict::kImproved: return "improved";
    case TimingVerdict::kUnreliable: return "unreliable";
    case TimingVerdict::kUndecided: return "undecided";
  }
  return "unreliable";
}

}  // namespace tcsb
