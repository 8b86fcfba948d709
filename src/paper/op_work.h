// OpWorkTally: the work counts of TreeCut operations (OpWork, softbody/op_sample.h) summarised per operation and per
// count as a maximum, a mean, and a mean over the interior calls (those whose block lies away from the net's border).
// Pure; the result JSON writes it per TC-SB case, and the op_work claims (op_work_claims.h) compare it across nets.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "softbody/op_sample.h"

namespace tcsb {

/// One count of one operation over many calls.
struct OpWorkStat {
  std::int32_t max = 0;      ///< the largest count of one call (0 when there was no call)
  double mean = 0;           ///< the mean count per call (0 when there was no call)
  double interior_mean = 0;  ///< the mean over interior calls (OpWork::interior; 0 when there was none)
};

/// One operation's counts over many calls.
struct OpWorkSummary {
  std::int64_t calls = 0;                              ///< calls summarised
  std::int64_t interior_calls = 0;                     ///< of which interior (OpWork::interior)
  std::array<OpWorkStat, kOpWorkCountKinds> counts{};  ///< indexed by OpWorkCount
  const OpWorkStat& operator[](OpWorkCount count) const { return counts[static_cast<std::size_t>(count)]; }
};

/// Accumulates OpSamples; O(1) per sample, no allocation, so it may sit behind an OpSink on a long run.
class OpWorkTally {
 public:
  /// Counts one operation call.
  void add(const OpSample& sample);
  /// Counts every call in `samples`.
  void add(std::span<const OpSample> samples) {
    for (const OpSample& s : samples) add(s);
  }
  /// The summary of one operation's calls so far.
  OpWorkSummary summary(OpKind kind) const;

 private:
  struct Sums {
    std::int64_t calls = 0, interior_calls = 0;
    std::array<std::int32_t, kOpWorkCountKinds> max{};
    std::array<std::int64_t, kOpWorkCountKinds> sum{}, interior_sum{};
  };
  std::array<Sums, kOpKindCount> by_kind_{};
};

}  // namespace tcsb
