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
  const auto add = [](std::vector<double>& into, const std::vector<double>& from) {
    for (const double t : from) {
      const bool known = std::any_of(into.begin(), into.end(), [&](double x) { return same_compression(x, t); });
      if (!known) into.push_back(t);
    }
  };
  add(m.tcsb_targets, b.tcsb_targets);
  add(m.equal_plain_targets, b.equal_plain_targets);
  return m;
}

std::vector<std::size_t> cases_in_scope(const RunResult& result, const ClaimScope& scope) {
  const auto at_one_of = [](const std::vector<double>& targets, double c) {
    return std::any_of(targets.begin(), targets.end(), [&](double t) { return same_compression(t, c); });
  };
  const auto selected = [&](const CaseKey& key) {
    if (key.method == Method::kPlain) return scope.plain;
    if (key.method == Method::kPlainEqual)
      return key.compression && at_one_of(scope.equal_plain_targets, *key.compression);
    if (key.method != Method::kTcsb || !key.compression) return false;
    if (scope.every_tcsb) return true;
    return at_one_of(scope.tcsb_targets, *key.compression);
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
