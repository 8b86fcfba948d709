// Paper tables and fits on hand-built results: Table 2 means and ratios, diverged cases left out, the paired
// same-run ratio, Table 1 shares and percentiles, and linear fits with a known slope.
#include "paper/paper_tables.h"

#include <gtest/gtest.h>

#include "../report/synthetic_run.h"

namespace tcsb {
namespace {

using testing::diverge;
using testing::make_case;
using testing::op;
using testing::synthetic_suite;

/// Two nets; plain, tcsb@1.0 and tcsb@0.5 on each, in the runner's case order.
RunResult two_nets_at_two_budgets() {
  RunResult r;
  r.suite = synthetic_suite(2);
  r.suite.compression = {1.0, 0.5};
  const Suite& s = r.suite;
  r.cases = {
      make_case(s, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0),
      make_case(s, 0, Method::kTcsb, 1.0, 100, 210, 0, 1.1),
      make_case(s, 0, Method::kTcsb, 0.5, 50, 100, 20, 0.5),
      make_case(s, 1, Method::kPlain, std::nullopt, 400, 800, 0, 3.0),
      make_case(s, 1, Method::kTcsb, 1.0, 400, 810, 0, 2.9),
      make_case(s, 1, Method::kTcsb, 0.5, 200, 400, 30, 1.5),
  };
  return r;
}

TEST(Table2, MeansOverNetsAndRatiosToPlain) {
  const std::vector<Table2Row> rows = table2(two_nets_at_two_budgets());
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].method, "plain");
  EXPECT_FALSE(rows[0].compression);
  EXPECT_EQ(rows[0].compression_label, "-");
  EXPECT_DOUBLE_EQ(*rows[0].N, 250);
  EXPECT_DOUBLE_EQ(*rows[0].L, 500);
  EXPECT_DOUBLE_EQ(*rows[0].I, 0);
  EXPECT_DOUBLE_EQ(*rows[0].total_ms, 2.0);
  EXPECT_DOUBLE_EQ(*rows[0].time_ratio_vs_plain, 1.0);
  EXPECT_DOUBLE_EQ(*rows[0].node_ratio, 1.0);
  EXPECT_EQ(rows[0].nets, 2);
  EXPECT_EQ(rows[0].status, "ok");

  EXPECT_EQ(rows[1].method, "tcsb");
  EXPECT_EQ(rows[1].compression, 1.0);
  EXPECT_EQ(rows[1].compression_label, "NoCompression");
  EXPECT_DOUBLE_EQ(*rows[1].total_ms, 2.0);
  EXPECT_DOUBLE_EQ(*rows[1].L, 510);

  EXPECT_EQ(rows[2].compression_label, "50%");
  EXPECT_DOUBLE_EQ(*rows[2].N, 125);
  EXPECT_DOUBLE_EQ(*rows[2].I, 25);
  EXPECT_DOUBLE_EQ(*rows[2].total_ms, 1.0);
  EXPECT_DOUBLE_EQ(*rows[2].time_ratio_vs_plain, 0.5);
  EXPECT_DOUBLE_EQ(*rows[2].node_ratio, 0.5);
}

TEST(Table2, CompressionLabels) {
  EXPECT_EQ(compression_label(std::nullopt), "-");
  EXPECT_EQ(compression_label(1.0), "NoCompression");
  EXPECT_EQ(compression_label(0.75), "75%");
  EXPECT_EQ(compression_label(0.3), "30%");  // 100 * 0.3 is 30.000000000000004 in binary
  EXPECT_EQ(compression_label(0.125), "12.5%");
}

TEST(Table2, DivergedCasesAreLeftOutAndTheRowIsPartial) {
  RunResult r = two_nets_at_two_budgets();
  diverge(r.cases[5], 17);  // n1/tcsb@0.5
  const std::vector<Table2Row> rows = table2(r);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[2].status, "partial");
  EXPECT_EQ(rows[2].nets, 1);
  EXPECT_DOUBLE_EQ(*rows[2].N, 50);
  EXPECT_DOUBLE_EQ(*rows[2].total_ms, 0.5);
  // Compared with plain on the same net only (plain's n1 would make the ratio look far better than it is).
  EXPECT_DOUBLE_EQ(*rows[2].time_ratio_vs_plain, 0.5);
  EXPECT_DOUBLE_EQ(*rows[2].node_ratio, 0.5);
  EXPECT_EQ(rows[0].status, "ok");
}

TEST(Table2, AllDivergedGivesNoNumbers) {
  RunResult r = two_nets_at_two_budgets();
  diverge(r.cases[2], 3);
  diverge(r.cases[5], 4);
  const Table2Row row = table2(r)[2];
  EXPECT_EQ(row.status, "diverged");
  EXPECT_EQ(row.nets, 0);
  EXPECT_FALSE(row.N);
  EXPECT_FALSE(row.total_ms);
  EXPECT_FALSE(row.time_ratio_vs_plain);
}

/// two_nets_at_two_budgets() with plain_equal at 0.5 on each net after the TC-SB cases, as the runner orders them.
RunResult two_nets_with_equal_plain() {
  RunResult r = two_nets_at_two_budgets();
  r.suite.methods.push_back(Method::kPlainEqual);
  const Suite& s = r.suite;
  r.cases.insert(r.cases.begin() + 3, make_case(s, 0, Method::kPlainEqual, 0.5, 49, 84, 0, 0.4));
  r.cases.push_back(make_case(s, 1, Method::kPlainEqual, 0.5, 196, 364, 0, 1.1));
  return r;
}

TEST(Table2, TcsbAgainstPlainEqualOfTheSameTarget) {
  const std::vector<Table2Row> rows = table2(two_nets_with_equal_plain());
  ASSERT_EQ(rows.size(), 4u);
  // Means over the nets, as the plain ratio: (0.5 + 1.5) / (0.4 + 1.1).
  EXPECT_EQ(rows[2].method, "tcsb");
  EXPECT_DOUBLE_EQ(*rows[2].time_ratio_vs_equal_plain, 2.0 / 1.5);
  EXPECT_FALSE(rows[1].time_ratio_vs_equal_plain);  // NoCompression has no plain_equal
  EXPECT_FALSE(rows[0].time_ratio_vs_equal_plain);
  EXPECT_EQ(rows[3].method, "plain_equal");
  EXPECT_EQ(rows[3].compression_label, "50%");
  EXPECT_DOUBLE_EQ(*rows[3].time_ratio_vs_plain, 1.5 / 4.0);
  EXPECT_FALSE(rows[3].time_ratio_vs_equal_plain);
  EXPECT_FALSE(table2(two_nets_at_two_budgets())[2].time_ratio_vs_equal_plain);  // no plain_equal cases: no ratio
}

TEST(Table2, EqualPlainRatioOnlyOverNetsOkInBoth) {
  RunResult r = two_nets_with_equal_plain();
  diverge(r.cases.back(), 5);  // n1/plain_equal@0.5
  EXPECT_DOUBLE_EQ(*table2(r)[2].time_ratio_vs_equal_plain, 0.5 / 0.4);
}

TEST(Table2, NoPlainMeansNoRatios) {
  RunResult r = two_nets_at_two_budgets();
  r.cases = {r.cases[1], r.cases[4]};
  const std::vector<Table2Row> rows = table2(r);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_FALSE(rows[0].time_ratio_vs_plain);
  EXPECT_FALSE(rows[0].node_ratio);
  EXPECT_DOUBLE_EQ(*rows[0].N, 250);
}

TEST(PairedRatio, MedianOverRepetitionsOkInBoth) {
  RunResult r;
  r.suite = synthetic_suite(1);
  r.cases = {make_case(r.suite, 0, Method::kPlain, std::nullopt, 10, 20, 0, 1.0, {1, 2, 2, 1, 5}),
             make_case(r.suite, 0, Method::kTcsb, 0.5, 5, 10, 1, 4.0, {2, 4, 6, 100, 7})};
  r.cases[1].repetitions[3].status = "diverged";
  // Pairing is by repetition number, not by position.
  std::swap(r.cases[0].repetitions[0], r.cases[0].repetitions[2]);
  r.cases[1].repetitions.pop_back();  // repetition 4 exists only in the base
  // ratios: 2/1, 4/2, 6/2 -> median 2
  EXPECT_DOUBLE_EQ(*paired_ratio(r, 1, 0), 2.0);
  EXPECT_DOUBLE_EQ(*paired_ratio(r, 0, 0), 1.0);
  EXPECT_FALSE(paired_ratio(r, 2, 0));
  EXPECT_FALSE(paired_ratio(r, 0, 9));
}

TEST(PairedRatio, PlainCaseOfTheSameNet) {
  const RunResult r = two_nets_at_two_budgets();
  EXPECT_EQ(plain_case_for(r, 2), 0u);
  EXPECT_EQ(plain_case_for(r, 4), 3u);
  EXPECT_EQ(plain_case_for(r, 3), 3u);
  EXPECT_FALSE(plain_case_for(r, 6));
  RunResult no_plain = r;
  no_plain.cases.erase(no_plain.cases.begin());
  EXPECT_FALSE(plain_case_for(no_plain, 0));
}

TEST(Table1, SharesMeansAndPercentiles) {
  RunResult r = two_nets_at_two_budgets();
  // refine: complete times 4, 8, 12, 16 us; node share 3/4 of the total.
  r.cases[2].ops.samples = {op(OpKind::kRefine, 3000, 1000, 100, 200), op(OpKind::kRefine, 6000, 2000, 110, 220)};
  r.cases[5].ops.samples = {op(OpKind::kRefine, 9000, 3000, 120, 240), op(OpKind::kRefine, 12000, 4000, 130, 260),
                            op(OpKind::kEndCoarse, 500, 500, 90, 180)};
  r.cases[1].ops.samples = {};
  const std::vector<Table1Row> rows = table1(r);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].operation, "refine");
  EXPECT_EQ(rows[1].operation, "end-refine");
  EXPECT_EQ(rows[2].operation, "coarse");
  EXPECT_EQ(rows[3].operation, "end-coarse");

  const Table1Row& refine = rows[0];
  EXPECT_EQ(refine.count, 4u);
  EXPECT_DOUBLE_EQ(refine.N, 115);
  EXPECT_DOUBLE_EQ(refine.L, 230);
  EXPECT_DOUBLE_EQ(refine.node_ops_ms, 0.0075);
  EXPECT_DOUBLE_EQ(refine.link_ops_ms, 0.0025);
  EXPECT_DOUBLE_EQ(refine.complete_ms, 0.01);
  EXPECT_DOUBLE_EQ(refine.node_ops_pct, 75);
  EXPECT_DOUBLE_EQ(refine.link_ops_pct, 25);
  EXPECT_DOUBLE_EQ(refine.p50_us, 10);             // between 8 and 12
  EXPECT_DOUBLE_EQ(refine.p99_us, 12 + 0.97 * 4);  // linear interpolation at rank 2.97

  EXPECT_EQ(rows[1].count, 0u);
  EXPECT_EQ(rows[1].complete_ms, 0);
  EXPECT_EQ(rows[1].node_ops_pct, 0);
  EXPECT_EQ(rows[3].count, 1u);
  EXPECT_DOUBLE_EQ(rows[3].node_ops_pct, 50);
}

TEST(Table1, DivergedCasesContributeNoSamples) {
  RunResult r = two_nets_at_two_budgets();
  r.cases[2].ops.samples = {op(OpKind::kCoarse, 1000, 1000, 10, 20)};
  r.cases[5].ops.samples = {op(OpKind::kCoarse, 900000, 1000, 10, 20)};
  diverge(r.cases[5], 9);
  const Table1Row coarse = table1(r)[2];
  EXPECT_EQ(coarse.count, 1u);
  EXPECT_DOUBLE_EQ(coarse.complete_ms, 0.002);
}

TEST(StepFit, KnownSlopeAscendingPoints) {
  RunResult r;
  r.suite = synthetic_suite(3);
  const Suite& s = r.suite;
  // ms = 0.5 + 0.001 * N for plain, given in descending N; tcsb has one usable net only.
  r.cases = {make_case(s, 0, Method::kPlain, std::nullopt, 900, 1800, 0, 1.4),
             make_case(s, 0, Method::kTcsb, 0.5, 450, 900, 5, 1.0),
             make_case(s, 1, Method::kPlain, std::nullopt, 400, 800, 0, 0.9),
             make_case(s, 1, Method::kTcsb, 0.5, 200, 400, 5, 1.0),
             make_case(s, 2, Method::kPlain, std::nullopt, 100, 200, 0, 0.6)};
  diverge(r.cases[3], 2);
  const std::vector<StepFit> fits = step_ms_vs_nodes(r);
  ASSERT_EQ(fits.size(), 1u);
  const StepFit& f = fits[0];
  EXPECT_EQ(f.method, "plain");
  EXPECT_FALSE(f.compression);
  EXPECT_TRUE(f.valid);
  EXPECT_NEAR(*f.slope_ms_per_node, 0.001, 1e-12);
  EXPECT_NEAR(*f.intercept_ms, 0.5, 1e-12);
  EXPECT_NEAR(*f.r2, 1.0, 1e-12);
  ASSERT_EQ(f.points.size(), 3u);
  EXPECT_EQ(f.points[0].nodes, 100);
  EXPECT_EQ(f.points[2].nodes, 900);
  EXPECT_EQ(f.points[2].ms, 1.4);
}

TEST(StepFit, DegenerateFitIsListedWithoutNumbers) {
  RunResult r;
  r.suite = synthetic_suite(2);
  r.cases = {make_case(r.suite, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0),
             make_case(r.suite, 1, Method::kPlain, std::nullopt, 100, 200, 0, 2.0)};
  const std::vector<StepFit> fits = step_ms_vs_nodes(r);
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_FALSE(fits[0].valid);
  EXPECT_FALSE(fits[0].slope_ms_per_node);
  EXPECT_FALSE(fits[0].intercept_ms);
  EXPECT_FALSE(fits[0].r2);
  EXPECT_EQ(fits[0].points.size(), 2u);
}

TEST(OpFit, OnePointPerNetPooledOverItsCasesAndFlatness) {
  RunResult r = two_nets_at_two_budgets();
  // n0: refine at 100 nodes taking 1 us (two cases pooled); n1: at 300 nodes taking 3 us.
  r.cases[1].ops.samples = {op(OpKind::kRefine, 800, 200, 100, 200)};
  r.cases[2].ops.samples = {op(OpKind::kRefine, 500, 500, 100, 200), op(OpKind::kRefine, 900, 100, 100, 200)};
  r.cases[5].ops.samples = {op(OpKind::kRefine, 2000, 1000, 300, 600), op(OpKind::kCoarse, 1000, 0, 300, 600)};
  r.cases[0].ops.samples = {op(OpKind::kRefine, 99999, 0, 5000, 600)};  // plain: never an operation of TC-SB
  const std::vector<OpFit> fits = op_ms_vs_nodes(r);
  ASSERT_EQ(fits.size(), 4u);
  const OpFit& refine = fits[0];
  EXPECT_EQ(refine.operation, "refine");
  ASSERT_TRUE(refine.valid);
  ASSERT_EQ(refine.points.size(), 2u);
  EXPECT_DOUBLE_EQ(refine.points[0].nodes, 100);
  EXPECT_DOUBLE_EQ(refine.points[0].ms, 0.001);
  EXPECT_DOUBLE_EQ(refine.points[1].ms, 0.003);
  EXPECT_NEAR(*refine.slope_ms_per_node, 1e-5, 1e-15);
  // slope * span / median = 1e-5 * 200 / 0.002
  EXPECT_NEAR(*refine.flatness, 1.0, 1e-9);

  EXPECT_EQ(fits[2].operation, "coarse");
  EXPECT_FALSE(fits[2].valid);  // one net only
  EXPECT_FALSE(fits[2].flatness);
  EXPECT_EQ(fits[2].points.size(), 1u);
  EXPECT_TRUE(fits[1].points.empty());
}

TEST(OpFit, ConstantCostIsFlat) {
  RunResult r = two_nets_at_two_budgets();
  r.cases[2].ops.samples = {op(OpKind::kEndRefine, 700, 300, 100, 200)};
  r.cases[5].ops.samples = {op(OpKind::kEndRefine, 600, 400, 400, 800)};
  const OpFit f = op_ms_vs_nodes(r)[1];
  ASSERT_TRUE(f.valid);
  EXPECT_NEAR(*f.flatness, 0.0, 1e-12);
  EXPECT_LT(*f.flatness, kFlatnessTarget);
}

}  // namespace
}  // namespace tcsb
