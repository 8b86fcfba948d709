#include "paper/op_work_claims.h"

#include <algorithm>
#include <optional>

#include "softbody/op_work_bounds.h"

namespace tcsb {

std::vector<NetOpWork> op_work_by_net(const RunResult& result) {
  std::vector<NetOpWork> nets;
  for (const CaseResult& c : result.cases) {
    if (c.key.method != Method::kTcsb) continue;
    auto it = std::find_if(nets.begin(), nets.end(), [&](const NetOpWork& n) { return n.net == c.net_name; });
    if (it == nets.end()) {
      nets.push_back({c.net_name, c.net_nodes, {}});
      it = nets.end() - 1;
    }
    it->tally.add(c.ops.samples);
  }
  return nets;
}

double relative_spread(const std::vector<double>& values) {
  if (values.empty()) return 0;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  return *hi > 0 ? (*hi - *lo) / *hi : 0;
}

namespace {

/// measured for one operation (see op_work_claims), or nullopt when it cannot be judged.
std::optional<double> worst_use(const std::vector<NetOpWork>& nets, OpKind kind) {
  if (nets.size() < 2) return std::nullopt;
  const OpWork& bound = op_work_bounds::bound(kind);
  std::vector<OpWorkSummary> summaries;
  for (const NetOpWork& n : nets) {
    summaries.push_back(n.tally.summary(kind));
    if (summaries.back().calls == 0 || summaries.back().interior_calls == 0) return std::nullopt;
  }
  double worst = 0;
  for (const OpWorkCount count : kOpWorkBoundedCounts) {
    const double limit = op_work_count(bound, count);
    for (const OpWorkSummary& s : summaries) {
      // A bound of 0 (no removal, so no relocation): any count exceeds it; 0 of 0 uses none of it.
      const double use = limit > 0 ? s[count].max / limit : (s[count].max > 0 ? s[count].max + 1.0 : 0.0);
      worst = std::max(worst, use);
    }
  }
  for (const OpWorkCount count : kOpWorkBlockLocalCounts) {
    std::vector<double> maxima, interior_means;
    for (const OpWorkSummary& s : summaries) {
      maxima.push_back(s[count].max);
      interior_means.push_back(s[count].interior_mean);
    }
    worst = std::max(worst, relative_spread(maxima) / kOpWorkSpreadTolerance);
    worst = std::max(worst, relative_spread(interior_means) / kOpWorkSpreadTolerance);
  }
  return worst;
}

}  // namespace

std::vector<Claim> op_work_claims(const RunResult& result) {
  const std::vector<NetOpWork> nets = op_work_by_net(result);
  std::vector<Claim> claims;
  for (int k = 0; k < kOpKindCount; ++k) {
    const auto kind = static_cast<OpKind>(k);
    const std::string name = op_kind_name(kind);
    claims.push_back(check_claim(
        "op_work_" + name,
        name + " does the same work on every net (Figure 4, operations constant in time): no count's maximum, the "
               "swap-with-last's relocated nodes and links included, exceeds the bound the cut's invariants give, and "
               "the nodes, links, tree records and DBVT leaves of its own block have the same maximum over all calls "
               "and the same mean over interior calls (block away from the border) on every net, within 5 %. "
               "Measured: the worst of maximum / bound and spread across nets / 5 % (pass <= 1)",
        Comparison::kAtMost, 1.0, 0.0, worst_use(nets, kind)));
  }
  return claims;
}

}  // namespace tcsb
