#include "harness/op_work.h"

#include <algorithm>

namespace tcsb {

void OpWorkTally::add(const OpSample& sample) {
  Sums& s = by_kind_[static_cast<std::size_t>(sample.kind)];
  ++s.calls;
  for (int k = 0; k < kOpWorkCountKinds; ++k) {
    const std::int32_t v = op_work_count(sample.work, static_cast<OpWorkCount>(k));
    s.max[static_cast<std::size_t>(k)] = std::max(s.max[static_cast<std::size_t>(k)], v);
    s.sum[static_cast<std::size_t>(k)] += v;
  }
}

OpWorkSummary OpWorkTally::summary(OpKind kind) const {
  const Sums& s = by_kind_[static_cast<std::size_t>(kind)];
  OpWorkSummary out;
  out.calls = s.calls;
  if (s.calls == 0) return out;
  for (std::size_t k = 0; k < out.counts.size(); ++k) {
    out.counts[k].max = s.max[k];
    out.counts[k].mean = static_cast<double>(s.sum[k]) / static_cast<double>(s.calls);
  }
  return out;
}

}  // namespace tcsb
