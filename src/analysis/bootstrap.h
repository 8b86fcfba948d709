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

/// One two-stage resample of units grouped by the process that measured them (`process_of[u]`: unit u's process,
/// any label): indices into the units. The processes are drawn again with replacement (in the order they first
/// appear), then, in each drawn process, its units with replacement. Resampling the processes first carries the
/// variation between processes into the interval, which drawing the units alone would hide when the units of one
/// process agree more than processes do (a net's ratio moves between processes more than within one). With one
/// process the process draw is skipped, so it is exactly resample_indices(process_of.size(), rng): an interval of a
/// run of one process is what it always was.
std::vector<std::size_t> resample_grouped(const std::vector<int>& process_of, std::mt19937_64& rng);

/// How many distinct processes `process_of` names (0 for no units).
std::size_t process_count(const std::vector<int>& process_of);

/// The central `confidence` interval of bootstrap replicates by the percentile method: the (1 - confidence) / 2 and
/// (1 + confidence) / 2 quantiles (linear interpolation). Non-finite replicates (a resample on which the statistic is
/// undefined) are dropped; nullopt when fewer than 20 remain. Throws std::invalid_argument unless 0 < confidence < 1.
std::optional<Interval> percentile_interval(std::vector<double> replicates, double confidence);

}  // namespace tcsb
