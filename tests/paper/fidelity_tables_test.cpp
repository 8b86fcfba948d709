// Fidelity tables from hand-made results: rows combine nets as documented, the Pareto front and the maximal
// compression follow their definitions, and the targets fail when they should.
#include "paper/fidelity_tables.h"

#include <gtest/gtest.h>

#include <tuple>

namespace tcsb {
namespace {

MetricSummary metric(double mean, double p95, double max) { return {400, mean, p95, max}; }

FidelityCase make(std::size_t net, std::string_view method, double compression, double rms, double step_ms,
                  double reference_ms = 2.0) {
  FidelityCase c;
  c.net = net;
  c.net_name = std::string("n").append(std::to_string(net));  // not "n" + ...: GCC 12 -Wrestrict false positive
  c.subject = fidelity_subject(method, compression);
  c.mean_nodes = 1000.0 * compression * (net + 1);
  c.rms_pct = metric(rms, 2 * rms, 3 * rms);
  c.max_pct = metric(4 * rms, 5 * rms, 6 * rms);
  c.weighted_rms_pct = metric(rms, rms, rms);
  c.popping_pct = metric(0.01, 0.1, 0.2 * (net + 1));
  c.energy_drift_pct = metric(1, 2, 3);
  c.step_ms = step_ms;
  c.reference_step_ms = reference_ms;
  return c;
}

TEST(FidelityRows, CombineNetsAsMeanOfMeansAndMaxOfMaxima) {
  FidelityResult r;
  r.cases = {make(0, "tcsb", 0.5, 1.0, 1.0, 2.0), make(1, "tcsb", 0.5, 3.0, 3.0, 6.0)};
  r.cases[1].switch_ms = 4.0;
  const std::vector<FidelityRow> rows = fidelity_rows(r);
  ASSERT_EQ(rows.size(), 1u);
  const FidelityRow& row = rows[0];
  EXPECT_EQ(row.method, "tcsb");
  EXPECT_EQ(row.nets, 2);
  EXPECT_EQ(row.status, "ok");
  EXPECT_DOUBLE_EQ(*row.N, (500.0 + 1000.0) / 2);
  EXPECT_DOUBLE_EQ(row.rms_pct.mean, 2.0);
  EXPECT_DOUBLE_EQ(row.rms_pct.p95, 4.0);
  EXPECT_DOUBLE_EQ(row.rms_pct.max, 9.0);
  EXPECT_DOUBLE_EQ(row.popping_pct.max, 0.4);
  EXPECT_DOUBLE_EQ(*row.worst_net_rms_pct, 3.0);
  EXPECT_DOUBLE_EQ(*row.time_ratio_vs_plain, (1.0 + 3.0) / (2.0 + 6.0));  // ratio of the means, as Table 2
  EXPECT_DOUBLE_EQ(*row.switch_ms, 4.0);
}

TEST(FidelityRows, LeaveDivergedNetsOut) {
  FidelityResult r;
  r.cases = {make(0, "uniform_grid", 0.3, 1.0, 1.0), make(1, "uniform_grid", 0.3, 50.0, 1.0),
             make(0, "switch_body", 0.3, 1.0, 1.0)};
  r.cases[1].status = "diverged";
  r.cases[2].status = "diverged";
  const std::vector<FidelityRow> rows = fidelity_rows(r);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].status, "partial");
  EXPECT_EQ(rows[0].nets, 1);
  EXPECT_DOUBLE_EQ(rows[0].rms_pct.mean, 1.0);
  EXPECT_EQ(rows[1].status, "diverged");
  EXPECT_EQ(rows[1].rms_pct.count, 0u);
  EXPECT_FALSE(rows[1].time_ratio_vs_plain);
}

std::vector<FidelityRow> sweep_rows(const std::vector<std::pair<double, double>>& compression_rms,
                                    const std::vector<double>& ratios) {
  FidelityResult r;
  for (std::size_t i = 0; i < compression_rms.size(); ++i)
    r.cases.push_back(make(0, "tcsb", compression_rms[i].first, compression_rms[i].second, ratios[i]));
  return fidelity_rows(r);
}

TEST(ParetoSweep, MarksTheNonDominatedPoints) {
  // ratio = step / 2: 0.1 -> 0.1 (rms 9), 0.5 -> 0.3 (rms 10: dominated by 0.1), 1.0 -> 0.5 (rms 0).
  const std::vector<ParetoPoint> sweep =
      pareto_sweep(sweep_rows({{1.0, 0.0}, {0.1, 9.0}, {0.5, 10.0}}, {1.0, 0.2, 0.6}));
  ASSERT_EQ(sweep.size(), 3u);
  EXPECT_EQ(sweep[0].compression, 0.1);  // ascending
  EXPECT_TRUE(sweep[0].on_front);
  EXPECT_FALSE(sweep[1].on_front);
  EXPECT_TRUE(sweep[2].on_front);
  EXPECT_DOUBLE_EQ(*sweep[1].time_ratio_vs_plain, 0.3);
}

TEST(MaxCompression, IsTheSmallestTargetBelowWhichNothingFails) {
  // 0.2 passes but 0.4 fails: the answer is 0.6, not 0.2.
  const std::vector<ParetoPoint> sweep =
      pareto_sweep(sweep_rows({{0.2, 0.5}, {0.4, 1.5}, {0.6, 0.9}, {0.8, 0.4}, {1.0, 0.0}}, {1, 1, 1, 1, 1}));
  const MaxCompression m = max_compression(sweep, 1.0);
  ASSERT_TRUE(m.compression);
  EXPECT_DOUBLE_EQ(*m.compression, 0.6);
  EXPECT_DOUBLE_EQ(*m.rms_pct, 0.9);
  EXPECT_DOUBLE_EQ(max_compression(sweep, 2.0).compression.value(), 0.2);
}

TEST(MaxCompression, TheMeanOverTheNetsIsJudgedBesideTheWorstNet) {
  // Mean and worst net RMS per target: the worst net fails at 0.5 (1.2 %), the mean only at 0.1 (1.1 %).
  std::vector<ParetoPoint> sweep;
  for (const auto& [compression, mean, worst] : std::vector<std::tuple<double, double, double>>{{0.1, 1.1, 2.5},
                                                                                                {0.2, 0.98, 1.3},
                                                                                                {0.3, 0.83, 0.99},
                                                                                                {0.5, 0.86, 1.2},
                                                                                                {0.75, 0.77, 0.95},
                                                                                                {1.0, 0.0, 0.0}}) {
    ParetoPoint p;
    p.compression = compression;
    p.rms_pct = mean;
    p.worst_net_rms_pct = worst;
    p.time_ratio_vs_plain = compression;
    sweep.push_back(p);
  }
  const MaxCompression m = max_compression(sweep, 1.0);
  EXPECT_DOUBLE_EQ(m.compression.value(), 0.75);
  ASSERT_TRUE(m.mean_compression);
  EXPECT_DOUBLE_EQ(*m.mean_compression, 0.2);
  EXPECT_DOUBLE_EQ(*m.mean_rms_pct, 0.98);
  EXPECT_DOUBLE_EQ(*m.mean_time_ratio_vs_plain, 0.2);
  sweep[4].rms_pct.reset();  // a target without a mean stops the descent, as a failing one does
  EXPECT_DOUBLE_EQ(max_compression(sweep, 1.0).mean_compression.value(), 1.0);
}

TEST(MaxCompression, IsAbsentWhenEvenTheLargestTargetFails) {
  const std::vector<ParetoPoint> sweep = pareto_sweep(sweep_rows({{0.5, 3.0}, {0.9, 2.0}}, {1, 1}));
  EXPECT_FALSE(max_compression(sweep, 1.0).compression);
  EXPECT_FALSE(max_compression({}, 1.0).compression);
}

TEST(FidelityTargets, PassAndFailAsMeasured) {
  FidelityResult r;
  r.cases = {make(0, "tcsb", 0.75, 0.8, 1.0), make(0, "tcsb", 0.3, 2.5, 1.0), make(0, "uniform_grid", 0.3, 6.0, 1.0)};
  const std::vector<Claim> targets = fidelity_targets(fidelity_rows(r));
  const auto find = [&](const std::string& id) -> const Claim& {
    for (const Claim& c : targets)
      if (c.id == id) return c;
    ADD_FAILURE() << "no target " << id;
    return targets.front();
  };
  EXPECT_TRUE(passed(find("fidelity_rms_75")));
  EXPECT_FALSE(passed(find("fidelity_rms_30")));
  EXPECT_DOUBLE_EQ(*find("fidelity_weighted_vs_uniform_30").measured, 2.5 / 6.0);
  EXPECT_TRUE(passed(find("fidelity_weighted_vs_uniform_30")));
  EXPECT_TRUE(passed(find("fidelity_popping_75")));  // 0.2 <= 0.5
  EXPECT_EQ(targets.size(), 5u);
}

TEST(FidelityTargets, CalibratedRowsAreJudgedAgainstTheConvergedTargets) {
  FidelityResult r;
  r.cases = {make(0, "tcsb_calibrated", 0.75, 0.4, 1.0), make(0, "tcsb_calibrated", 0.3, 1.5, 1.0),
             make(0, "uniform_grid_calibrated", 0.3, 3.0, 1.0), make(0, "uniform_grid_calibrated", 0.75, 0.5, 1.0)};
  const std::vector<Claim> targets = fidelity_targets(fidelity_rows(r));
  const auto find = [&](const std::string& id) -> const Claim* {
    for (const Claim& c : targets)
      if (c.id == id) return &c;
    return nullptr;
  };
  ASSERT_NE(find("fidelity_calibrated_rms_75"), nullptr);
  EXPECT_TRUE(passed(*find("fidelity_calibrated_rms_75")));   // 0.4 <= 0.5
  EXPECT_FALSE(passed(*find("fidelity_calibrated_rms_30")));  // 1.5 > 1
  ASSERT_NE(find("fidelity_calibrated_weighted_vs_uniform_30"), nullptr);
  EXPECT_DOUBLE_EQ(*find("fidelity_calibrated_weighted_vs_uniform_30")->measured, 1.5 / 3.0);
  EXPECT_TRUE(passed(*find("fidelity_calibrated_weighted_vs_uniform_30")));
  EXPECT_FALSE(passed(*find("fidelity_calibrated_weighted_vs_uniform_75")));  // 0.8 > 0.7
}

TEST(FidelityTargets, NoCalibratedTargetsWithoutACalibration) {
  FidelityResult r;
  r.cases = {make(0, "tcsb", 0.75, 0.8, 1.0), make(0, "tcsb", 0.3, 2.5, 1.0)};
  for (const Claim& c : fidelity_targets(fidelity_rows(r))) EXPECT_EQ(c.id.find("calibrated"), std::string::npos);
}

TEST(FidelityTargets, FailWhenNothingWasMeasured) {
  const std::vector<Claim> targets = fidelity_targets({});
  ASSERT_EQ(targets.size(), 2u);
  EXPECT_FALSE(passed(targets[0]));
  EXPECT_FALSE(passed(targets[1]));
  EXPECT_FALSE(targets[0].measured);
}

TEST(FidelityTables, HoldEveryPieceAtThePassThreshold) {
  FidelityResult r;
  r.rms_threshold_pct = 1.5;
  r.cases = {make(0, "tcsb", 1.0, 0.0, 2.0), make(0, "tcsb", 0.5, 1.0, 1.0), make(0, "tcsb", 0.3, 2.0, 0.5),
             make(0, "tcsb_calibrated", 0.5, 0.5, 1.0)};
  const FidelityTables t = fidelity_tables(r);
  const std::vector<FidelityRow> rows = fidelity_rows(r);
  ASSERT_EQ(t.rows.size(), rows.size());
  EXPECT_EQ(t.sweep.size(), pareto_sweep(rows).size());
  EXPECT_EQ(t.max_compression.threshold_pct, 1.5);
  EXPECT_EQ(t.max_compression.compression, max_compression(pareto_sweep(rows), 1.5).compression);
  EXPECT_EQ(t.max_compression.compression, 0.5);  // 0.3 errs 2 % > 1.5 %
  ASSERT_EQ(t.calibrated_sweep.size(), 1u);
  EXPECT_EQ(t.calibrated_max_compression.compression, 0.5);
  EXPECT_EQ(t.targets.size(), fidelity_targets(rows).size());
}

}  // namespace
}  // namespace tcsb
