// The percentile bootstrap: how far a statistic computed from a few noisy repetitions could move if the run were
// repeated. A resample draws the units (here: repetitions) again with replacement; the spread of the statistic over
// many resamples gives its interval. Used so a claim's verdict on this shared, noisy machine comes with a measure of
// whether it is decided or within the run's noise.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace tcsb {

/// A closed interval [low, high].
struct Interval {
  double low = 0.0;
  double high = 0.0;
  bool contains(double x) const { return low <= x && x <= high; }
};

/// One bootstrap resample of n units: n indices drawn uniformly from [0, n) with replacement. The same generator
/// state gives the same indices on every platform (std::uniform_int_distribution's algorithm is unspecified, so it
/// is not used).
std::vector<std::size_t> resample_indices(std::size_t n, std::mt19937_64& rng);

/// One two-stage resample of grouped units (e.g. runs, each with its repetitions): the groups are drawn again with
/// replacement, then, in each drawn group, its units with replacement; returns the drawn values, pooled. Resampling
/// the groups first carries the variation between groups into the interval, which pooling the units alone would
/// hide when units of one group agree more than groups do (repetitions of one process, runs in different
/// processes). With one group it is resample_indices over that group's units. Empty groups contribute nothing.
std::vector<double> resample_groups(const std::vector<std::vector<double>>& groups, std::mt19937_64& rng);

/// The central `confidence` interval of bootstrap replicates by the percentile method: the (1 - confidence) / 2 and
/// (1 + confidence) / 2 quantiles (linear interpolation). Non-finite replicates (a resample on which the statistic is
/// undefined) are dropped; nullopt when fewer than 20 remain. Throws std::invalid_argument unless 0 < confidence < 1.
std::optional<Interval> percentile_interval(std::vector<double> replicates, double confidence);

}  // namespace tcsb
