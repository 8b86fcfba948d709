#include "harness/op_work_claims.h"

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
  double worst = 0;
  for (const OpWorkCount count : kOpWorkWitnessCounts) {
    std::vector<double> maxima, means;
    for (const NetOpWork& n : nets) {
      const OpWorkSummary s = n.tally.summary(kind);
      if (s.calls == 0) return std::nullopt;
      maxima.push_back(s[count].max);
      means.push_back(s[count].mean);
      worst = std::max(worst, static_cast<double>(s[count].max) / op_work_count(bound, count));
    }
    worst = std::max(worst, relative_spread(maxima) / kOpWorkSpreadTolerance);
    worst = std::max(worst, relative_spread(means) / kOpWorkSpreadTolerance);
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
        name + " does the same work on every net (Figure 4, operations constant in time): the nodes, links, tree "
               "records and DBVT leaves one call touches have the same maximum and mean on every net, within 5 %, and "
               "no maximum exceeds the bound the cut's invariants give. Measured: the worst of spread / 5 % and "
               "maximum / bound (pass <= 1)",
        Comparison::kAtMost, 1.0, 0.0, worst_use(nets, kind)));
  }
  return claims;
}

}  // namespace tcsb
