// Which cases a claim's extra repetitions and bootstrap read: plain_equal cases only when the scope names their
// target, and a net's plain case beside its TC-SB cases.
#include "paper/claim_scope.h"

#include <gtest/gtest.h>

namespace tcsb {
namespace {

/// One net: plain, tcsb@0.75, tcsb@0.3, plain_equal@0.75, plain_equal@0.3 (the runner's order).
RunResult one_net() {
  RunResult r;
  const std::pair<Method, std::optional<double>> keys[] = {{Method::kPlain, std::nullopt},
                                                           {Method::kTcsb, 0.75},
                                                           {Method::kTcsb, 0.3},
                                                           {Method::kPlainEqual, 0.75},
                                                           {Method::kPlainEqual, 0.3}};
  for (const auto& [method, compression] : keys) r.cases.emplace_back().key = CaseKey{0, method, compression};
  return r;
}

TEST(ClaimScope, PlainEqualCasesOnlyAtTheNamedTargets) {
  const RunResult r = one_net();
  EXPECT_EQ(cases_in_scope(r, ClaimScope{.tcsb_targets = {0.3}, .equal_plain_targets = {0.3}}),
            (std::vector<std::size_t>{0, 2, 4}));
  // A paper claim's scope never pulls plain_equal in, not even with every TC-SB case.
  EXPECT_EQ(cases_in_scope(r, ClaimScope{.plain = true, .tcsb_targets = {}, .every_tcsb = true}),
            (std::vector<std::size_t>{0, 1, 2}));
}

TEST(ClaimScope, MergedUnitesEqualPlainTargets) {
  const ClaimScope m =
      merged(ClaimScope{.equal_plain_targets = {0.3}}, ClaimScope{.equal_plain_targets = {0.75, 0.3 + 1e-12}});
  EXPECT_EQ(m.equal_plain_targets.size(), 2u);
  EXPECT_EQ(cases_in_scope(one_net(), m), (std::vector<std::size_t>{3, 4}));
}

}  // namespace
}  // namespace tcsb
