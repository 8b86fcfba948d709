// The CI gate's decision on timings: a metric regresses only when its slowdown is both statistically significant
// and larger than a threshold. Significance is a one-sided Mann–Whitney U test per metric with Holm–Bonferroni
// over every metric decided together, so the chance that an unchanged tree fails the gate stays at alpha however
// many cases a suite has (twelve independent tests at 5 % each would fail an unchanged tree almost every other
// run). Pure: samples in, decisions out.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace tcsb {

/// How strict the gate is.
struct GateSettings {
  double alpha = 0.05;          ///< family-wise false-alarm rate over all metrics decided together, in (0, 1)
  double threshold = 0.05;      ///< smallest relative change of the median that counts (0.05 = 5 %), >= 0
  std::size_t min_samples = 9;  ///< fewer samples on either side: "unreliable", never decided
};

/// One metric's samples (one value per repetition) in the base run and in the new run.
struct TimingSamples {
  std::vector<double> base;
  std::vector<double> next;
};

/// What the gate concludes about one metric.
enum class TimingVerdict {
  kUnchanged,   ///< no significant change beyond the threshold
  kRegressed,   ///< significantly larger (slower) by more than the threshold
  kImproved,    ///< significantly smaller (faster) by more than the threshold
  kUnreliable,  ///< too few samples on a side, or no defined change: reported, never decided
};

/// The decision about one metric; every number is finite.
struct TimingDecision {
  std::size_t base_count = 0, next_count = 0;  ///< samples on each side
  std::optional<double> base_median;           ///< nullopt for an empty sample
  std::optional<double> next_median;
  std::optional<double> change;  ///< next median / base median - 1; nullopt when undefined
  /// Holm-adjusted one-sided p-value in the direction of the change (larger: next > base, else next < base);
  /// compare it with alpha directly. nullopt when the metric is unreliable.
  std::optional<double> p_value;
  TimingVerdict verdict = TimingVerdict::kUnreliable;
};

/// Decides every metric of `family` together (the Holm correction runs over the reliable ones). Throws
/// std::invalid_argument on a non-finite sample value, alpha outside (0, 1) or a negative or non-finite threshold.
std::vector<TimingDecision> decide_timings(std::span<const TimingSamples> family, const GateSettings& settings);

/// Holm–Bonferroni adjusted p-values, in input order: p_(i) * (m - i) for the i-th smallest (0-based), made
/// non-decreasing in that order and capped at 1. Rejecting where adjusted <= alpha keeps the family-wise error at
/// alpha. Throws std::invalid_argument on a value outside [0, 1].
std::vector<double> holm_adjust(std::span<const double> p_values);

/// "unchanged", "regressed", "improved" or "unreliable".
const char* verdict_name(TimingVerdict verdict);

}  // namespace tcsb
