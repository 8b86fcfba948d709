#include "paper/equal_error_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "analysis/statistics.h"

namespace tcsb {

namespace {

/// Resamples per interval: enough that a 95 % percentile interval moves by less than its last digit shown.
constexpr int kBootstrapResamples = 1000;

double median_of(const std::vector<double>& blocks, const std::vector<std::size_t>& pick, std::vector<double>& tmp) {
  tmp.clear();
  for (const std::size_t k : pick) tmp.push_back(blocks[k]);
  return median(tmp);
}

std::vector<CurvePoint> curve_of(const std::vector<TimedCurvePoint>& points, const std::vector<double>& times) {
  std::vector<CurvePoint> curve;
  for (std::size_t i = 0; i < points.size(); ++i) curve.push_back({times[i], points[i].point.error});
  return curve;
}

std::vector<EqualErrorPoint> points_of(std::vector<TimedCurvePoint> points) {
  std::stable_sort(points.begin(), points.end(), [](const TimedCurvePoint& a, const TimedCurvePoint& b) {
    return a.point.time_ms < b.point.time_ms;
  });
  std::vector<EqualErrorPoint> out;
  for (const TimedCurvePoint& p : points) out.push_back(p.point);
  return out;
}

/// The curves of one net and the interval's resampling of their blocks.
class NetCurves {
 public:
  NetCurves(std::vector<TimedCurvePoint> tcsb, std::vector<TimedCurvePoint> grid, std::vector<TimedCurvePoint> full,
            std::size_t blocks)
      : tcsb_(std::move(tcsb)), grid_(std::move(grid)), full_(std::move(full)), blocks_(blocks) {}

  void fill(EqualErrorNet& net, std::uint64_t seed) const {
    net.tcsb = points_of(tcsb_);
    net.grid = points_of(grid_);
    net.full = points_of(full_);
    net.grid_monotone = is_monotone(curve_of(grid_, times(grid_)));
    net.full_monotone = is_monotone(curve_of(full_, times(full_)));
    net.tcsb_monotone = is_monotone(curve_of(tcsb_, times(tcsb_)));
    std::vector<std::vector<double>> grid_replicates(tcsb_.size()), full_replicates(tcsb_.size());
    std::mt19937_64 rng(seed);
    std::vector<double> tmp;
    for (int b = 0; b < kBootstrapResamples; ++b) {
      const std::vector<std::size_t> pick = resample_indices(blocks_, rng);
      const auto resampled = [&](const std::vector<TimedCurvePoint>& points) {
        std::vector<double> t;
        for (const TimedCurvePoint& p : points) t.push_back(median_of(*p.blocks, pick, tmp));
        return t;
      };
      const std::vector<double> tcsb = resampled(tcsb_), grid = resampled(grid_), full = resampled(full_);
      for (std::size_t i = 0; i < tcsb_.size(); ++i) {
        grid_replicates[i].push_back(ratio(time_at_error(curve_of(grid_, grid), tcsb_[i].point.error), tcsb[i]));
        full_replicates[i].push_back(ratio(time_at_error(curve_of(full_, full), tcsb_[i].point.error), tcsb[i]));
      }
    }
    std::vector<std::size_t> order(tcsb_.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return tcsb_[a].point.compression < tcsb_[b].point.compression;
    });
    for (const std::size_t i : order) {
      const EqualErrorPoint& p = tcsb_[i].point;
      EqualErrorRow row;
      row.compression = p.compression;
      row.nodes = p.nodes;
      row.time_ms = p.time_ms;
      row.error = p.error;
      row.grid = rival(grid_, p, grid_replicates[i]);
      row.full = rival(full_, p, full_replicates[i]);
      net.rows.push_back(row);
    }
  }

 private:
  static std::vector<double> times(const std::vector<TimedCurvePoint>& points) {
    std::vector<double> t;
    for (const TimedCurvePoint& p : points) t.push_back(p.point.time_ms);
    return t;
  }
  /// The speed-up of a replicate: only where the rival's curve is interpolated (a bound or no value is no sample).
  static double ratio(const TimeAtError& at, double tcsb_ms) {
    if (at.status != EqualErrorStatus::kInterpolated || !(tcsb_ms > 0)) return std::numeric_limits<double>::quiet_NaN();
    return at.time_ms / tcsb_ms;
  }
  static EqualErrorRival rival(const std::vector<TimedCurvePoint>& curve, const EqualErrorPoint& tcsb,
                               std::vector<double> replicates) {
    const TimeAtError at = time_at_error(curve_of(curve, times(curve)), tcsb.error);
    EqualErrorRival r;
    r.status = at.status;
    if (at.status == EqualErrorStatus::kNotReached) return r;
    r.time_ms = at.time_ms;
    r.speedup = at.time_ms / tcsb.time_ms;
    if (at.status == EqualErrorStatus::kInterpolated) r.interval = percentile_interval(std::move(replicates), 0.95);
    return r;
  }

  std::vector<TimedCurvePoint> tcsb_, grid_, full_;
  std::size_t blocks_;
};

/// The net's error metric of a case: p95 pixels with a camera, else the RMS; nullopt when not measured.
std::optional<double> case_error(const FidelityCase& c, bool camera) {
  if (camera) return c.screen ? summary_mean(c.screen->p95_px) : std::nullopt;
  return summary_mean(c.rms_pct);
}

EqualErrorNet net_table(const FidelityResult& result, const FidelityFloors& floors, std::uint64_t seed) {
  EqualErrorNet net;
  net.net = floors.net_name;
  const bool camera = std::any_of(result.cases.begin(), result.cases.end(),
                                  [&](const FidelityCase& c) { return c.net == floors.net && c.screen; });
  net.metric = camera ? "p95_px" : "rms_pct";
  const std::optional<double> floor = !camera               ? summary_mean(floors.noise_rms_pct)
                                      : floors.noise_screen ? summary_mean(floors.noise_screen->p95_px)
                                                            : std::nullopt;
  const std::vector<double>& reference_blocks = floors.reference_block_step_ms;
  if (!floor || !(*floor > 0)) {
    net.missing = "no noise floor (the perturbed reference diverged, or the result predates floors): the "
                  "reference's point on the curves is its noise floor";
    return net;
  }
  net.floor = *floor;
  if (reference_blocks.empty()) {
    net.missing = "the reference's blocks were not timed (it diverged, or the result predates block times)";
    return net;
  }
  std::vector<TimedCurvePoint> tcsb, grid, full;
  const TimedCurvePoint reference{{.method = "reference", .time_ms = median(reference_blocks), .error = *floor},
                                  &reference_blocks};
  for (const FidelityCase& c : result.cases) {
    if (c.net != floors.net || c.status != "ok" || c.block_step_ms.size() != reference_blocks.size()) continue;
    const std::optional<double> error = case_error(c, camera);
    if (!error) continue;
    // Below the noise floor an error is not resolved; the floor keeps the log-log curves defined.
    TimedCurvePoint p{{.method = c.subject.method,
                       .compression = c.subject.body.compression,
                       .solver_divisor = c.subject.body.solver_divisor,
                       .nodes = c.mean_nodes,
                       .time_ms = median(c.block_step_ms),
                       .error = std::max(*error, *floor)},
                      &c.block_step_ms};
    if (c.subject.method == "tcsb" && c.subject.body.compression < 1.0) tcsb.push_back(p);
    if (c.subject.method == "uniform_grid") grid.push_back(p);
    if (c.subject.method == "full_resolution") full.push_back(p);
  }
  TimedCurvePoint top = reference;
  if (!full.empty()) top.point.nodes = full.front().point.nodes;
  grid.push_back(top);
  full.push_back(top);
  if (tcsb.empty())
    net.missing = "no TC-SB budget below 1 ran to the end";
  else if (grid.size() < 2)
    net.missing = "no uniform grid ran to the end (fidelity.curves.budgets)";
  else if (full.size() < 2)
    net.missing = "no full-resolution body at fewer passes ran to the end (fidelity.curves.solver_divisors)";
  if (!net.missing.empty()) return net;
  fill_equal_error(std::move(tcsb), std::move(grid), std::move(full), reference_blocks.size(), seed, net);
  return net;
}

}  // namespace

void fill_equal_error(std::vector<TimedCurvePoint> tcsb, std::vector<TimedCurvePoint> grid,
                      std::vector<TimedCurvePoint> full, std::size_t blocks, std::uint64_t seed, EqualErrorNet& out) {
  NetCurves(std::move(tcsb), std::move(grid), std::move(full), blocks).fill(out, seed);
}

std::vector<EqualErrorNet> equal_error_table(const FidelityResult& result, std::uint64_t seed) {
  const bool curves = std::any_of(result.cases.begin(), result.cases.end(),
                                  [](const FidelityCase& c) { return c.subject.method == "full_resolution"; });
  std::vector<EqualErrorNet> out;
  if (!curves) return out;
  for (const FidelityFloors& f : result.floors) out.push_back(net_table(result, f, seed + f.net));
  return out;
}

}  // namespace tcsb
