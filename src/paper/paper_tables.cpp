#include "paper/paper_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include "analysis/linear_fit.h"
#include "analysis/relative_change.h"
#include "analysis/statistics.h"
#include "base/case_pairing.h"

namespace tcsb {
namespace {

/// A case whose numbers may be averaged: every repetition ok and a finite step-time summary. Anything else is
/// left out of tables and fits, never averaged in.
bool usable(const CaseResult& c) {
  return c.status == "ok" && c.step_ms.count > 0 && std::isfinite(c.step_ms.median) && std::isfinite(c.mean_nodes) &&
         std::isfinite(c.mean_links) && std::isfinite(c.mean_interpolations);
}

/// Cases of one (method, compression) group, in case order.
struct Group {
  Method method = Method::kPlain;
  std::optional<double> compression;
  std::vector<std::size_t> cases;
};

std::vector<Group> groups_of(const RunResult& result) {
  std::vector<Group> groups;
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseKey& key = result.cases[i].key;
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const Group& g) { return g.method == key.method && g.compression == key.compression; });
    if (it == groups.end()) it = groups.insert(groups.end(), Group{key.method, key.compression, {}});
    it->cases.push_back(i);
  }
  return groups;
}

/// The usable plain case of a net, if any.
const CaseResult* usable_plain(const RunResult& result, std::size_t net) {
  for (const CaseResult& c : result.cases) {
    if (c.key.net == net && c.key.method == Method::kPlain) return usable(c) ? &c : nullptr;
  }
  return nullptr;
}

/// The usable plain_equal case of a net at a compression target, if any.
const CaseResult* usable_equal_plain(const RunResult& result, std::size_t net, double compression) {
  for (const CaseResult& c : result.cases) {
    if (c.key.net == net && c.key.method == Method::kPlainEqual && c.key.compression &&
        same_compression(*c.key.compression, compression))
      return usable(c) ? &c : nullptr;
  }
  return nullptr;
}

/// Mean of `field` over the given cases; nullopt for none.
template <class Field>
std::optional<double> mean_over(const std::vector<const CaseResult*>& cases, Field field) {
  if (cases.empty()) return std::nullopt;
  std::vector<double> values;
  values.reserve(cases.size());
  for (const CaseResult* c : cases) values.push_back(field(*c));
  return mean(values);
}

double complete_ns(const OpSample& s) { return static_cast<double>(s.node_ns) + static_cast<double>(s.link_ns); }

/// The op samples of every usable TC-SB case (they are not kept per repetition, so a case with any diverged
/// repetition contributes none).
template <class Visit>
void for_each_op_sample(const RunResult& result, Visit visit) {
  for (const CaseResult& c : result.cases) {
    if (c.key.method != Method::kTcsb || !usable(c)) continue;
    for (const OpSample& s : c.ops.samples) visit(c, s);
  }
}

/// Fits ms against nodes; points are sorted ascending by nodes first (and non-finite ones dropped, defensively:
/// fit_linear rejects them).
template <class Fit>
void fit_points(std::vector<ScalingPoint> points, Fit& fit) {
  std::erase_if(points, [](const ScalingPoint& p) { return !std::isfinite(p.nodes) || !std::isfinite(p.ms); });
  std::sort(points.begin(), points.end(),
            [](const ScalingPoint& a, const ScalingPoint& b) { return a.nodes < b.nodes; });
  std::vector<double> x, y;
  for (const ScalingPoint& p : points) {
    x.push_back(p.nodes);
    y.push_back(p.ms);
  }
  const LinearFit line = fit_linear(x, y);
  fit.valid = line.valid;
  if (line.valid) {
    fit.slope_ms_per_node = line.slope;
    fit.intercept_ms = line.intercept;
    fit.r2 = line.r2;
  }
  fit.points = std::move(points);
}

/// The log-log slope of a step fit's points (all positive), when they define one.
std::optional<double> loglog_exponent(const std::vector<ScalingPoint>& points) {
  std::vector<double> x, y;
  for (const ScalingPoint& p : points) {
    if (!(p.nodes > 0 && p.ms > 0)) return std::nullopt;
    x.push_back(std::log(p.nodes));
    y.push_back(std::log(p.ms));
  }
  const LinearFit line = fit_linear(x, y);
  return line.valid ? std::optional(line.slope) : std::nullopt;
}

/// A case as the pairing rule sees it (base/case_pairing.h): its net and configuration, and its method.
auto pairing_key(const CaseResult& c) {
  const PairingRole role = c.key.method == Method::kPlain        ? PairingRole::kPlain
                           : c.key.method == Method::kPlainEqual ? PairingRole::kPlainEqual
                           : c.key.method == Method::kTcsb       ? PairingRole::kTcsb
                                                                 : PairingRole::kOther;
  return PairingKey{std::tie(c.key.net, c.key.configuration), role, c.key.compression};
}

}  // namespace

std::string compression_percent(double compression) {
  return std::to_string(static_cast<int>(std::lround(compression * 100)));
}

std::string compression_label(std::optional<double> compression) {
  if (!compression) return "-";
  if (*compression == 1.0) return "NoCompression";
  // %g with 6 significant digits hides binary noise such as 100 * 0.3 = 30.000000000000004.
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g%%", *compression * 100.0);
  return buf;
}

std::vector<Table2Row> table2(const RunResult& result) {
  std::vector<Table2Row> rows;
  for (const Group& g : groups_of(result)) {
    Table2Row row;
    row.method = method_name(g.method);
    row.compression = g.compression;
    row.compression_label = compression_label(g.compression);
    std::vector<const CaseResult*> ok, ok_with_plain, plain_of_those, ok_with_equal, equal_of_those;
    for (const std::size_t i : g.cases) {
      const CaseResult& c = result.cases[i];
      if (!usable(c)) continue;
      ok.push_back(&c);
      if (const CaseResult* plain = usable_plain(result, c.key.net)) {
        ok_with_plain.push_back(&c);
        plain_of_those.push_back(plain);
      }
      if (g.method != Method::kTcsb || !g.compression) continue;
      if (const CaseResult* equal = usable_equal_plain(result, c.key.net, *g.compression)) {
        ok_with_equal.push_back(&c);
        equal_of_those.push_back(equal);
      }
    }
    row.nets = static_cast<int>(ok.size());
    row.status = ok.size() == g.cases.size() ? "ok" : ok.empty() ? "diverged" : "partial";
    row.N = mean_over(ok, [](const CaseResult& c) { return c.mean_nodes; });
    row.L = mean_over(ok, [](const CaseResult& c) { return c.mean_links; });
    row.I = mean_over(ok, [](const CaseResult& c) { return c.mean_interpolations; });
    row.total_ms = mean_over(ok, [](const CaseResult& c) { return c.step_ms.median; });
    if (!ok_with_plain.empty()) {
      const auto ms = [](const CaseResult& c) { return c.step_ms.median; };
      const auto nodes = [](const CaseResult& c) { return c.mean_nodes; };
      row.time_ratio_vs_plain = safe_ratio(*mean_over(ok_with_plain, ms), *mean_over(plain_of_those, ms));
      row.node_ratio = safe_ratio(*mean_over(ok_with_plain, nodes), *mean_over(plain_of_those, nodes));
    }
    if (!ok_with_equal.empty()) {
      // Averaged over the nets as the plain ratio is (Table 2's way), not a mean of per-net ratios.
      const auto ms = [](const CaseResult& c) { return c.step_ms.median; };
      row.time_ratio_vs_equal_plain = safe_ratio(*mean_over(ok_with_equal, ms), *mean_over(equal_of_those, ms));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::optional<double> paired_ratio(const RunResult& result, std::size_t case_index, std::size_t base_case_index) {
  if (case_index >= result.cases.size() || base_case_index >= result.cases.size()) return std::nullopt;
  std::vector<double> ratios;
  for_each_repetition_pair(result.cases[case_index].repetitions, result.cases[base_case_index].repetitions,
                           [&](const RepetitionResult& r, const RepetitionResult& b) {
                             if (const auto q = safe_ratio(r.mean_step_ms, b.mean_step_ms)) ratios.push_back(*q);
                           });
  if (ratios.empty()) return std::nullopt;
  return median(ratios);
}

std::optional<std::size_t> plain_case_for(const RunResult& result, std::size_t case_index) {
  return plain_partner(result.cases, case_index, pairing_key);
}

std::optional<std::size_t> equal_plain_case_for(const RunResult& result, std::size_t case_index) {
  return equal_plain_partner(result.cases, case_index, pairing_key);
}

std::vector<Table1Row> table1(const RunResult& result) {
  struct Pool {
    std::vector<double> nodes, links, node_ms, link_ms, complete_us;
  };
  std::vector<Pool> pools(kOpKindCount);
  for_each_op_sample(result, [&](const CaseResult&, const OpSample& s) {
    Pool& p = pools[static_cast<std::size_t>(s.kind)];
    p.nodes.push_back(s.nodes);
    p.links.push_back(s.links);
    p.node_ms.push_back(s.node_ns / 1e6);
    p.link_ms.push_back(s.link_ns / 1e6);
    p.complete_us.push_back(complete_ns(s) / 1e3);
  });
  std::vector<Table1Row> rows;
  for (int k = 0; k < kOpKindCount; ++k) {
    const Pool& p = pools[static_cast<std::size_t>(k)];
    Table1Row row;
    row.operation = op_kind_name(static_cast<OpKind>(k));
    row.count = p.nodes.size();
    if (row.count > 0) {
      row.N = mean(p.nodes);
      row.L = mean(p.links);
      row.node_ops_ms = mean(p.node_ms);
      row.link_ops_ms = mean(p.link_ms);
      row.complete_ms = row.node_ops_ms + row.link_ops_ms;
      if (const auto share = safe_ratio(row.node_ops_ms, row.complete_ms)) {
        row.node_ops_pct = 100.0 * *share;
        row.link_ops_pct = 100.0 - row.node_ops_pct;
      }
      row.p50_us = percentile(p.complete_us, 50.0);
      row.p99_us = percentile(p.complete_us, 99.0);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<StepFit> step_ms_vs_nodes(const RunResult& result) {
  std::vector<StepFit> fits;
  for (const Group& g : groups_of(result)) {
    std::vector<ScalingPoint> points;
    for (const std::size_t i : g.cases) {
      const CaseResult& c = result.cases[i];
      if (usable(c)) points.push_back({c.mean_nodes, c.step_ms.median});
    }
    if (points.size() < 2) continue;
    StepFit fit;
    fit.method = method_name(g.method);
    fit.compression = g.compression;
    fit_points(std::move(points), fit);
    fits.push_back(std::move(fit));
  }
  return fits;
}

StepFit step_fit_of_method(const RunResult& result, Method method) {
  StepFit fit;
  fit.method = method_name(method);
  std::vector<ScalingPoint> points;
  for (const CaseResult& c : result.cases)
    if (c.key.method == method && usable(c)) points.push_back({c.mean_nodes, c.step_ms.median});
  if (points.size() < 2) return fit;
  fit_points(std::move(points), fit);
  if (fit.valid) fit.loglog_exponent = loglog_exponent(fit.points);
  return fit;
}

std::vector<OpFit> op_ms_vs_nodes(const RunResult& result) {
  // kind -> net -> (nodes, complete ms) of every sample; std::map keeps nets in suite order.
  std::vector<std::map<std::size_t, std::pair<std::vector<double>, std::vector<double>>>> per_net(kOpKindCount);
  for_each_op_sample(result, [&](const CaseResult& c, const OpSample& s) {
    auto& [nodes, ms] = per_net[static_cast<std::size_t>(s.kind)][c.key.net];
    nodes.push_back(s.nodes);
    ms.push_back(complete_ns(s) / 1e6);
  });
  std::vector<OpFit> fits;
  for (int k = 0; k < kOpKindCount; ++k) {
    OpFit fit;
    fit.operation = op_kind_name(static_cast<OpKind>(k));
    std::vector<ScalingPoint> points;
    for (const auto& [net, samples] : per_net[static_cast<std::size_t>(k)]) {
      points.push_back({mean(samples.first), median(samples.second)});
    }
    fit_points(std::move(points), fit);
    if (fit.valid) {
      std::vector<double> ms;
      for (const ScalingPoint& p : fit.points) ms.push_back(p.ms);
      const double span = fit.points.back().nodes - fit.points.front().nodes;
      fit.flatness = safe_ratio(*fit.slope_ms_per_node * span, median(ms));
    }
    fits.push_back(std::move(fit));
  }
  return fits;
}

}  // namespace tcsb
