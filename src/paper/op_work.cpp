#include "paper/op_work.h"

#include <algorithm>

namespace tcsb {

void OpWorkTally::add(const OpSample& sample) {
  Sums& s = by_kind_[static_cast<std::size_t>(sample.kind)];
  ++s.calls;
  if (sample.work.interior) ++s.interior_calls;
  for (std::size_t k = 0; k < s.max.size(); ++k) {
    const std::int32_t v = op_work_count(sample.work, static_cast<OpWorkCount>(k));
    s.max[k] = std::max(s.max[k], v);
    s.sum[k] += v;
    if (sample.work.interior) s.interior_sum[k] += v;
  }
}

OpWorkSummary OpWorkTally::summary(OpKind kind) const {
  const Sums& s = by_kind_[static_cast<std::size_t>(kind)];
  OpWorkSummary out;
  out.calls = s.calls;
  out.interior_calls = s.interior_calls;
  if (s.calls == 0) return out;
  for (std::size_t k = 0; k < out.counts.size(); ++k) {
    out.counts[k].max = s.max[k];
    out.counts[k].mean = static_cast<double>(s.sum[k]) / static_cast<double>(s.calls);
    if (s.interior_calls > 0)
      out.counts[k].interior_mean = static_cast<double>(s.interior_sum[k]) / static_cast<double>(s.interior_calls);
  }
  return out;
}

}  // namespace tcsb
