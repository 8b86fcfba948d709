// The CI gate's decision on timings, in three verdicts like `tcsb reproduce`'s claims (analysis/claim.h): a metric's
// relative change of the median (new / base - 1) gets a bootstrap interval, and the threshold is the margin. The
// whole interval above the threshold: regressed; the whole interval at or below it: no regression; across it:
// undecided, with how many more repetitions would likely decide. Each end of an interval is a one-sided test at
// alpha / m over the m metrics decided together (Bonferroni), so the chance that an unchanged tree fails the gate
// stays at alpha however many cases a suite has. The one-sided Mann–Whitney U test per metric (Holm over the family)
// is reported beside it. Pure: samples in, decisions out.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "analysis/bootstrap.h"

namespace tcsb {

/// How strict the gate is.
struct GateSettings {
  double alpha = 0.05;          ///< family-wise false-alarm rate over all metrics decided together, in (0, 1)
  double threshold = 0.05;      ///< smallest relative change of the median that counts (0.05 = 5 %), >= 0
  std::size_t min_samples = 9;  ///< fewer samples on either side: "unreliable", never decided
  std::uint64_t seed = 1;       ///< the bootstrap's: the same samples give the same verdicts in every run
};

/// One metric's samples (one value per repetition) in the base run and in the new run, each with the process that
/// measured it (a merged result's shard): the interval resamples a run's processes first, then their repetitions
/// (resample_grouped), so a merged run's spread between processes enters it. Empty: one process per run.
struct TimingSamples {
  std::vector<double> base;
  std::vector<double> next;
  std::vector<int> base_process{};  ///< per base sample, or empty
  std::vector<int> next_process{};  ///< per next sample, or empty
};

/// What the gate concludes about one metric.
enum class TimingVerdict {
  kUnchanged,   ///< no regression: the whole interval is at or below the threshold
  kRegressed,   ///< the whole interval is above the threshold
  kImproved,    ///< the whole interval is below minus the threshold (faster)
  kUnreliable,  ///< too few samples on a side, or no defined change: reported, never decided
  kUndecided,   ///< the interval holds changes on both sides of the threshold: more repetitions would tell
};

/// The decision about one metric; every number is finite.
struct TimingDecision {
  std::size_t base_count = 0, next_count = 0;          ///< samples on each side
  std::size_t base_processes = 1, next_processes = 1;  ///< processes that measured them, which the interval pools
  std::optional<double> base_median;                   ///< nullopt for an empty sample
  std::optional<double> next_median;
  std::optional<double> change;  ///< next median / base median - 1; nullopt when undefined
  /// Holm-adjusted one-sided p-value in the direction of the change (larger: next > base, else next < base);
  /// compare it with alpha directly. nullopt when the metric is unreliable.
  std::optional<double> p_value;
  /// Where the change could lie had both runs been repeated: the percentile bootstrap over each side's samples
  /// (resampled apart: the runs' repetitions are not paired; a merged run's processes first), each end a one-sided
  /// test at alpha / m. nullopt when unreliable.
  std::optional<Interval> interval;
  double confidence = 0;  ///< the interval's (two-sided) confidence, 1 - 2 alpha / m; 0 without one
  /// Undecided only: repetitions per run that would likely decide, assuming the change stays where it is and the
  /// interval narrows as 1 / sqrt(repetitions); nullopt when the change sits on the threshold (none would).
  std::optional<int> more_repetitions;
  TimingVerdict verdict = TimingVerdict::kUnreliable;
};

/// Decides every metric of `family` together (the Holm correction runs over the reliable ones). Throws
/// std::invalid_argument on a non-finite sample value, a process list of another length than its samples, alpha
/// outside (0, 1) or a negative or non-finite threshold.
std::vector<TimingDecision> decide_timings(std::span<const TimingSamples> family, const GateSettings& settings);

/// Holm–Bonferroni adjusted p-values, in input order: p_(i) * (m - i) for the i-th smallest (0-based), made
/// non-decreasing in that order and capped at 1. Rejecting where adjusted <= alpha keeps the family-wise error at
/// alpha. Throws std::invalid_argument on a value outside [0, 1].
std::vector<double> holm_adjust(std::span<const double> p_values);

/// The extra repetitions per run after which an interval now at [low, high] around `change`, from `n` repetitions,
/// would likely lie on one side of `threshold`: the end facing the threshold moves toward `change` as
/// sqrt(n / (n + extra)). nullopt when `change` equals the threshold or the interval already lies on one side; at
/// most kMaxMoreRepetitions.
std::optional<int> repetitions_to_decide(double change, const Interval& interval, double threshold, std::size_t n);

/// The most repetitions repetitions_to_decide() proposes: beyond it, "more than this".
inline constexpr int kMaxMoreRepetitions = 1000;

/// "unchanged", "regressed", "improved", "unreliable" or "undecided".
const char* verdict_name(TimingVerdict verdict);

}  // namespace tcsb
