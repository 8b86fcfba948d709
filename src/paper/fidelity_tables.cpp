#include "paper/fidelity_tables.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/statistics.h"
#include "paper/paper_tables.h"

namespace tcsb {

namespace {

/// The mean of `values`, or nullopt when there are none or any is not finite (then nothing is averaged in).
std::optional<double> finite_mean(const std::vector<double>& values) {
  if (values.empty() || count_nonfinite(values) > 0) return std::nullopt;
  return mean(values);
}

/// Combines per-net summaries: means of mean and p95, max of max. Count 0 (unmeasured) if any part is not finite.
MetricSummary combine(const std::vector<const MetricSummary*>& parts) {
  MetricSummary out;
  std::vector<double> means, p95s, maxima;
  for (const MetricSummary* s : parts) {
    means.push_back(s->mean);
    p95s.push_back(s->p95);
    maxima.push_back(s->max);
  }
  const std::optional<double> m = finite_mean(means), p = finite_mean(p95s);
  if (!m || !p || count_nonfinite(maxima) > 0) return out;
  out.count = parts.size();
  out.mean = *m;
  out.p95 = *p;
  out.max = *std::max_element(maxima.begin(), maxima.end());
  return out;
}

const FidelityRow* row_of(const std::vector<FidelityRow>& rows, const char* method, double compression) {
  for (const FidelityRow& r : rows)
    if (r.method == method && same_compression(r.compression, compression)) return &r;
  return nullptr;
}

/// A row's metric when the row has ok nets.
std::optional<double> measured(const FidelityRow* row, double MetricSummary::*field,
                               MetricSummary FidelityRow::*metric) {
  if (row == nullptr || row->nets == 0) return std::nullopt;
  return (row->*metric).*field;
}

/// The floors of net `net`, or null when the result has none for it.
const FidelityFloors* floors_of(const FidelityResult& result, std::size_t net) {
  for (const FidelityFloors& f : result.floors)
    if (f.net == net) return &f;
  return nullptr;
}

/// Mean over `cases`' nets of a floor picked from each net's floors (nullopt from `pick`: that net has none); nullopt
/// unless every net has it.
template <class Pick>
std::optional<double> mean_floor(const FidelityResult& result, const std::vector<const FidelityCase*>& cases,
                                 Pick pick) {
  std::vector<double> values;
  for (const FidelityCase* c : cases) {
    const FidelityFloors* f = floors_of(result, c->net);
    const std::optional<double> v = f ? pick(*f) : std::nullopt;
    if (!v) return std::nullopt;
    values.push_back(*v);
  }
  return finite_mean(values);
}

}  // namespace

std::vector<FidelityRow> fidelity_rows(const FidelityResult& result) {
  std::vector<FidelityRow> rows;
  std::vector<std::vector<const FidelityCase*>> members;
  for (const FidelityCase& c : result.cases) {
    const std::string method = c.subject.method;
    auto it = std::find_if(rows.begin(), rows.end(), [&](const FidelityRow& r) {
      return r.method == method && same_compression(r.compression, c.subject.body.compression) &&
             r.solver_divisor == c.subject.body.solver_divisor;
    });
    if (it == rows.end()) {
      rows.push_back({});
      rows.back().method = method;
      rows.back().compression = c.subject.body.compression;
      rows.back().solver_divisor = c.subject.body.solver_divisor;
      members.emplace_back();
      it = rows.end() - 1;
    }
    members[static_cast<std::size_t>(it - rows.begin())].push_back(&c);
  }
  for (std::size_t k = 0; k < rows.size(); ++k) {
    FidelityRow& row = rows[k];
    std::vector<const FidelityCase*> ok;
    for (const FidelityCase* c : members[k])
      if (c->status == "ok" && c->rms_pct.count > 0) ok.push_back(c);
    row.nets = static_cast<int>(ok.size());
    row.status = ok.size() == members[k].size() ? "ok" : ok.empty() ? "diverged" : "partial";
    std::vector<const MetricSummary*> rms, max, weighted, popping, drift;
    std::vector<double> nodes, ms, reference_ms, switch_ms;
    for (const FidelityCase* c : ok) {
      rms.push_back(&c->rms_pct);
      max.push_back(&c->max_pct);
      weighted.push_back(&c->weighted_rms_pct);
      popping.push_back(&c->popping_pct);
      if (c->energy_drift_pct.count > 0) drift.push_back(&c->energy_drift_pct);
      nodes.push_back(c->mean_nodes);
      ms.push_back(c->step_ms);
      reference_ms.push_back(c->reference_step_ms);
      if (c->switch_ms) switch_ms.push_back(*c->switch_ms);
      if (!c->grid.empty() && row.grid.find(c->grid) == std::string::npos)
        row.grid += (row.grid.empty() ? "" : ",") + c->grid;
    }
    row.rms_pct = combine(rms);
    row.max_pct = combine(max);
    row.weighted_rms_pct = combine(weighted);
    row.popping_pct = combine(popping);
    row.energy_drift_pct = combine(drift);
    if (ok.empty()) continue;
    row.N = finite_mean(nodes);
    if (row.rms_pct.count > 0)
      for (const MetricSummary* r : rms) row.worst_net_rms_pct = std::max(row.worst_net_rms_pct.value_or(0.0), r->mean);
    const std::optional<double> subject = finite_mean(ms), reference = finite_mean(reference_ms);
    if (subject && reference && *reference > 0) row.time_ratio_vs_plain = *subject / *reference;
    row.switch_ms = finite_mean(switch_ms);
    row.noise_floor_pct = mean_floor(result, ok, [](const FidelityFloors& f) { return summary_mean(f.noise_rms_pct); });
    row.interpolation_floor_pct = mean_floor(result, ok, [&](const FidelityFloors& f) -> std::optional<double> {
      for (const InterpolationFloor& i : f.interpolation)
        if (same_compression(i.compression, row.compression)) return summary_mean(i.rms_pct);
      return std::nullopt;
    });
  }
  return rows;
}

std::vector<ParetoPoint> pareto_sweep(const std::vector<FidelityRow>& rows, const std::string& method) {
  std::vector<ParetoPoint> sweep;
  for (const FidelityRow& r : rows) {
    if (r.method != method) continue;
    ParetoPoint p;
    p.compression = r.compression;
    if (r.nets > 0) {
      p.N = r.N;
      p.time_ratio_vs_plain = r.time_ratio_vs_plain;
      p.rms_pct = r.rms_pct.mean;
      p.worst_net_rms_pct = r.worst_net_rms_pct;
    }
    sweep.push_back(p);
  }
  std::sort(sweep.begin(), sweep.end(),
            [](const ParetoPoint& a, const ParetoPoint& b) { return a.compression < b.compression; });
  for (ParetoPoint& p : sweep) {
    if (!p.time_ratio_vs_plain || !p.rms_pct) continue;
    p.on_front = std::none_of(sweep.begin(), sweep.end(), [&](const ParetoPoint& q) {
      if (&q == &p || !q.time_ratio_vs_plain || !q.rms_pct) return false;
      const bool no_worse = *q.time_ratio_vs_plain <= *p.time_ratio_vs_plain && *q.rms_pct <= *p.rms_pct;
      const bool better = *q.time_ratio_vs_plain < *p.time_ratio_vs_plain || *q.rms_pct < *p.rms_pct;
      return no_worse && better;
    });
  }
  return sweep;
}

namespace {

/// The smallest-budget point of the sweep at which it and every larger target keep `error` within `threshold_pct`:
/// from the largest budget down, the last target before the first failure (or a missing value); null if none.
const ParetoPoint* smallest_within(const std::vector<ParetoPoint>& sweep, std::optional<double> ParetoPoint::*error,
                                   double threshold_pct) {
  const ParetoPoint* best = nullptr;
  for (auto it = sweep.rbegin(); it != sweep.rend(); ++it) {
    if (!((*it).*error) || *((*it).*error) > threshold_pct) break;
    best = &*it;
  }
  return best;
}

}  // namespace

MaxCompression max_compression(const std::vector<ParetoPoint>& sweep, double threshold_pct) {
  MaxCompression m;
  m.threshold_pct = threshold_pct;
  if (const ParetoPoint* p = smallest_within(sweep, &ParetoPoint::worst_net_rms_pct, threshold_pct)) {
    m.compression = p->compression;
    m.rms_pct = p->worst_net_rms_pct;
    m.time_ratio_vs_plain = p->time_ratio_vs_plain;
  }
  if (const ParetoPoint* p = smallest_within(sweep, &ParetoPoint::rms_pct, threshold_pct)) {
    m.mean_compression = p->compression;
    m.mean_rms_pct = p->rms_pct;
    m.mean_time_ratio_vs_plain = p->time_ratio_vs_plain;
  }
  return m;
}

namespace {

/// Saliency-weighted RMS of `subject` over `grid`'s (the uniform grid of the same budget); none when either was not
/// measured (or the grid's is 0).
std::optional<double> weighted_rms_ratio(const FidelityRow* subject, const FidelityRow& grid) {
  const auto weighted = [](const FidelityRow* r) {
    return measured(r, &MetricSummary::mean, &FidelityRow::weighted_rms_pct);
  };
  const std::optional<double> a = weighted(subject), b = weighted(&grid);
  if (a && b && *b > 0) return *a / *b;
  return std::nullopt;
}

/// The converged regime's targets, for a suite with a calibration (its rows `tcsb_calibrated` and
/// `uniform_grid_calibrated`): calibrated TC-SB within 0.5 % RMS at 75 % and 1 % at 30 %, and its saliency-weighted
/// RMS at most 0.7 x the calibrated uniform grid's of the same node count, the fair rival.
void add_calibrated_targets(const std::vector<FidelityRow>& rows, std::vector<Claim>& targets) {
  struct RmsLimit {
    double compression, limit_pct;
    const char* text;
  };
  for (const auto& [compression, limit, text] : {RmsLimit{0.75, 0.5, "0.5"}, RmsLimit{0.3, 1.0, "1"}}) {
    const FidelityRow* row = row_of(rows, "tcsb_calibrated", compression);
    if (row == nullptr) continue;
    const std::string p = compression_percent(compression);
    targets.push_back(check_claim("fidelity_calibrated_rms_" + p,
                                  "calibrated TC-SB at " + p + "%: RMS error at most " + text +
                                      "% of the net's extent (mean over steps and nets)",
                                  Comparison::kAtMost, limit, 0.0,
                                  measured(row, &MetricSummary::mean, &FidelityRow::rms_pct)));
  }
  for (const FidelityRow& grid : rows) {
    if (grid.method != "uniform_grid_calibrated") continue;
    const FidelityRow* tc = row_of(rows, "tcsb_calibrated", grid.compression);
    if (tc == nullptr) continue;
    const std::string p = compression_percent(grid.compression);
    targets.push_back(check_claim("fidelity_calibrated_weighted_vs_uniform_" + p,
                                  "calibrated TC-SB at " + p +
                                      "%: saliency-weighted RMS at most 0.7 x the calibrated uniform grid's "
                                      "with the same node count (ratio)",
                                  Comparison::kAtMost, 0.7, 0.0, weighted_rms_ratio(tc, grid)));
  }
}

}  // namespace

std::vector<Claim> fidelity_targets(const std::vector<FidelityRow>& rows) {
  std::vector<Claim> targets;
  const auto rms = [&](double c) {
    return measured(row_of(rows, "tcsb", c), &MetricSummary::mean, &FidelityRow::rms_pct);
  };
  targets.push_back(check_claim("fidelity_rms_75",
                                "TC-SB at 75%: RMS error at most 1% of the net's extent (mean over "
                                "steps and nets)",
                                Comparison::kAtMost, 1.0, 0.0, rms(0.75)));
  targets.push_back(check_claim("fidelity_rms_30",
                                "TC-SB at 30%: RMS error at most 2% of the net's extent (mean over "
                                "steps and nets)",
                                Comparison::kAtMost, 2.0, 0.0, rms(0.3)));
  for (const FidelityRow& uniform : rows) {
    if (uniform.method != "uniform_grid") continue;
    const std::string p = compression_percent(uniform.compression);
    targets.push_back(check_claim("fidelity_weighted_vs_uniform_" + p,
                                  "TC-SB at " + p +
                                      "%: saliency-weighted RMS at most half the uniform coarse grid's "
                                      "with the same node count (ratio)",
                                  Comparison::kAtMost, 0.5, 0.0,
                                  weighted_rms_ratio(row_of(rows, "tcsb", uniform.compression), uniform)));
  }
  add_calibrated_targets(rows, targets);
  for (const FidelityRow& r : rows) {
    if (r.method != "tcsb" || r.compression >= 1.0) continue;
    const std::string p = compression_percent(r.compression);
    targets.push_back(check_claim("fidelity_popping_" + p,
                                  "TC-SB at " + p +
                                      "%: no operation moves the reconstructed surface by more than "
                                      "0.5% of the net's extent (max over steps and nets)",
                                  Comparison::kAtMost, 0.5, 0.0,
                                  measured(&r, &MetricSummary::max, &FidelityRow::popping_pct)));
  }
  return targets;
}

FidelityTables fidelity_tables(const FidelityResult& result) {
  FidelityTables t;
  t.rows = fidelity_rows(result);
  t.sweep = pareto_sweep(t.rows);
  t.max_compression = max_compression(t.sweep, result.rms_threshold_pct);
  t.calibrated_sweep = pareto_sweep(t.rows, "tcsb_calibrated");
  t.calibrated_max_compression = max_compression(t.calibrated_sweep, result.rms_threshold_pct);
  t.targets = fidelity_targets(t.rows);
  t.equal_error = equal_error_table(result);
  return t;
}

}  // namespace tcsb
