#include "harness/paper_claims.h"

#include <cmath>
#include <string>

namespace tcsb {

namespace {

const Table2Row* tcsb_row(const std::vector<Table2Row>& table2, double compression) {
  for (const Table2Row& r : table2)
    if (r.method == "tcsb" && r.compression && same_compression(*r.compression, compression)) return &r;
  return nullptr;
}

std::optional<double> ratio_of(const std::vector<Table2Row>& table2, double compression) {
  const Table2Row* r = tcsb_row(table2, compression);
  return r ? r->time_ratio_vs_plain : std::nullopt;
}

}  // namespace

std::vector<Claim> paper_claims(const PaperReference& paper, const std::vector<Table2Row>& table2,
                                const std::vector<StepFit>& step_fits, const std::vector<OpFit>& op_fits) {
  std::vector<Claim> claims;
  for (double target : {0.3, 0.75}) {
    const std::string p = compression_percent(target);
    const double expected = paper.time_ratio(p + "%");
    claims.push_back(check_claim("tcsb_" + p + "_vs_plain",
                                 "TC-SB at " + p + "% costs at most the paper's share of plain Bullet's step time "
                                 "(Table 2)",
                                 Comparison::kAtMost, expected, 0.0, ratio_of(table2, target)));
  }
  claims.push_back(check_claim("tcsb_nocompression_vs_plain",
                               "TC-SB without compression costs at most 1.03 x plain Bullet (Table 2: 10.08 vs 11.09 ms)",
                               Comparison::kAtMost, 1.03, 0.0, ratio_of(table2, 1.0)));
  for (const StepFit& fit : step_fits) {
    if (fit.method == "bullet_patch") continue;
    const std::string target = fit.compression ? compression_percent(*fit.compression) : "?";
    const std::string id = fit.method == "plain" ? std::string("plain") : "tcsb_" + target;
    claims.push_back(check_claim("step_linear_" + id,
                                 "step time of " + id + " is linear in node count, R^2 of the fit (Figure 5)",
                                 Comparison::kAtLeast, 0.98, 0.0, fit.r2));
  }
  for (const OpFit& fit : op_fits) {
    claims.push_back(check_claim("op_flat_" + fit.operation,
                                 fit.operation + " cost does not grow with node count: fitted slope x node range / "
                                                 "median cost (Figure 4)",
                                 Comparison::kAtMost, kFlatnessTarget, 0.0, fit.flatness));
  }
  return claims;
}

std::vector<Claim> project_targets(const std::vector<Table2Row>& table2, double wall_s) {
  std::vector<Claim> targets;
  targets.push_back(check_claim("target_30_vs_plain", "TC-SB at 30% costs at most 0.40 x plain Bullet",
                                Comparison::kAtMost, 0.40, 0.0, ratio_of(table2, 0.3)));
  std::optional<double> overhead;
  if (const Table2Row* r = tcsb_row(table2, 0.3); r && r->time_ratio_vs_plain && r->node_ratio && *r->node_ratio > 0)
    overhead = *r->time_ratio_vs_plain / *r->node_ratio;
  targets.push_back(check_claim("target_30_vs_node_ratio",
                                "TC-SB at 30%: time ratio over node ratio at most 1.10 (feedback, operations and "
                                "blending under 10%)",
                                Comparison::kAtMost, 1.10, 0.0, overhead));
  targets.push_back(check_claim("target_75_vs_plain", "TC-SB at 75% costs at most 0.80 x plain Bullet",
                                Comparison::kAtMost, 0.80, 0.0, ratio_of(table2, 0.75)));
  targets.push_back(check_claim("target_wall_time", "the reproduction finishes within 120 s", Comparison::kAtMost,
                                120.0, 0.0, wall_s));
  return targets;
}

}  // namespace tcsb
