#include "paper/claim_scope.h"

#include <algorithm>
#include <set>

#include "paper/paper_tables.h"

namespace tcsb {

ClaimScope merged(const ClaimScope& a, const ClaimScope& b) {
  ClaimScope m = a;
  m.plain = a.plain || b.plain;
  m.every_tcsb = a.every_tcsb || b.every_tcsb;
  m.operations = a.operations || b.operations;
  for (const double t : b.tcsb_targets) {
    const bool known =
        std::any_of(m.tcsb_targets.begin(), m.tcsb_targets.end(), [&](double x) { return same_compression(x, t); });
    if (!known) m.tcsb_targets.push_back(t);
  }
  return m;
}

std::vector<std::size_t> cases_in_scope(const RunResult& result, const ClaimScope& scope) {
  const auto selected = [&](const CaseKey& key) {
    if (key.method == Method::kPlain) return scope.plain;
    if (key.method != Method::kTcsb || !key.compression) return false;
    if (scope.every_tcsb) return true;
    return std::any_of(scope.tcsb_targets.begin(), scope.tcsb_targets.end(),
                       [&](double t) { return same_compression(t, *key.compression); });
  };
  std::set<std::size_t> nets_with_tcsb;
  for (const CaseResult& c : result.cases)
    if (c.key.method == Method::kTcsb && selected(c.key)) nets_with_tcsb.insert(c.key.net);
  std::vector<std::size_t> cases;
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseKey& key = result.cases[i].key;
    const bool paired_plain = key.method == Method::kPlain && nets_with_tcsb.contains(key.net);
    if (selected(key) || paired_plain) cases.push_back(i);
  }
  return cases;
}

bool all_among(const std::vector<std::size_t>& cases, const std::vector<std::size_t>& ran) {
  return std::all_of(cases.begin(), cases.end(),
                     [&](std::size_t c) { return std::find(ran.begin(), ran.end(), c) != ran.end(); });
}

}  // namespace tcsb
