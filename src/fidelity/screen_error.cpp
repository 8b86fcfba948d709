#include "fidelity/screen_error.h"

#include <algorithm>

#include "analysis/statistics.h"

namespace tcsb {

ScreenError screen_error(const ScreenProjection& view, std::span<const Eigen::Vector3d> subject,
                         std::span<const Eigen::Vector3d> reference, std::span<const std::uint8_t> seen,
                         std::vector<double>& scratch) {
  scratch.clear();
  const std::size_t n = std::min(subject.size(), reference.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!seen.empty() && !seen[i]) continue;
    const ScreenPoint r = view.project(reference[i]);
    if (!r.in_view) continue;
    scratch.push_back(view.displacement_px(subject[i], r));
  }
  ScreenError e;
  e.in_view = scratch.size();
  if (scratch.empty()) return e;
  const Summary s = summarize(scratch);
  e.mean = s.mean;
  e.p95 = s.p95;
  e.max = s.max;
  return e;
}

void ScreenErrorSeries::add(const ScreenError& e) {
  in_view_.push_back(static_cast<double>(e.in_view));
  if (e.in_view == 0) return;
  mean_.push_back(e.mean);
  p95_.push_back(e.p95);
  max_.push_back(e.max);
}

ScreenMetrics ScreenErrorSeries::finish() const {
  ScreenMetrics m;
  m.mean_px = summarize_metric(mean_);
  m.p95_px = summarize_metric(p95_);
  m.max_px = summarize_metric(max_);
  const auto over = std::count_if(p95_.begin(), p95_.end(), [](double p) { return p > 1.0; });
  m.p95_over_1px_share = p95_.empty() ? 0.0 : static_cast<double>(over) / static_cast<double>(p95_.size());
  m.points_in_view = in_view_.empty() ? 0.0 : mean(in_view_);
  return m;
}

}  // namespace tcsb
