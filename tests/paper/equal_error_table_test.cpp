// The speed-up at equal error from a hand-made fidelity pass: the curves, the interpolated rival times, their
// intervals, and a clear line where an input is missing.
#include "paper/equal_error_table.h"

#include <gtest/gtest.h>

namespace tcsb {
namespace {

constexpr std::size_t kPassBlocks = 12;

FidelityCase timed_case(std::string_view method, double compression, double rms, double ms, int divisor = 1) {
  FidelityCase c;
  c.net_name = std::string("n");
  c.subject = fidelity_subject(method, compression, divisor);
  c.mean_nodes = 1000.0 * compression;
  c.rms_pct = {400, rms, rms, rms};
  // Blocks alternate ±5 % around the time: a median of `ms`, and an interval with some width.
  for (std::size_t b = 0; b < kPassBlocks; ++b) c.block_step_ms.push_back(ms * (b % 2 ? 1.05 : 0.95));
  return c;
}

FidelityResult pass_with_curves() {
  FidelityResult r;
  FidelityFloors f;
  f.net_name = std::string("n");
  f.noise_rms_pct = {400, 0.01, 0.01, 0.01};
  f.reference_block_step_ms.assign(kPassBlocks, 8.0);
  r.floors = {f};
  r.cases = {timed_case("tcsb", 0.3, 5.0, 1.0),
             timed_case("tcsb", 1.0, 0.0, 8.0),  // full resolution: on no curve of TC-SB
             timed_case("uniform_grid", 0.1, 20.0, 0.5),
             timed_case("uniform_grid", 0.3, 10.0, 1.0),
             timed_case("uniform_grid", 0.5, 2.5, 4.0),
             timed_case("full_resolution", 1.0, 40.0, 2.0, 2)};
  return r;
}

TEST(EqualErrorTable, ReadsEachRivalsTimeAtTcsbsErrorOffItsCurve) {
  const std::vector<EqualErrorNet> nets = equal_error_table(pass_with_curves());
  ASSERT_EQ(nets.size(), 1u);
  const EqualErrorNet& n = nets[0];
  EXPECT_EQ(n.metric, "rms_pct");
  EXPECT_TRUE(n.missing.empty()) << n.missing;
  ASSERT_EQ(n.rows.size(), 1u);
  const EqualErrorRow& row = n.rows[0];
  EXPECT_DOUBLE_EQ(row.compression, 0.3);
  EXPECT_DOUBLE_EQ(row.error, 5.0);
  EXPECT_DOUBLE_EQ(row.time_ms, 1.0);
  // The grids: error 10 at 1 ms and 2.5 at 4 ms, a line of slope -1 in log-log: error 5 at 2 ms.
  EXPECT_EQ(row.grid.status, EqualErrorStatus::kInterpolated);
  EXPECT_NEAR(*row.grid.time_ms, 2.0, 1e-9);
  EXPECT_NEAR(*row.grid.speedup, 2.0, 1e-9);
  ASSERT_TRUE(row.grid.interval);
  // Each median moves by at most 5 % under resampling: the ratio stays within (0.95 / 1.05)^2 of 2 and around it.
  EXPECT_LE(row.grid.interval->low, 2.0);
  EXPECT_GE(row.grid.interval->high, 2.0);
  EXPECT_GT(row.grid.interval->low, 1.5);
  EXPECT_LT(row.grid.interval->high, 2.5);
  // Full resolution at half the passes (40 % at 2 ms) and the reference (its noise floor, 0.01 %, at 8 ms).
  EXPECT_EQ(row.full.status, EqualErrorStatus::kInterpolated);
  EXPECT_GT(*row.full.time_ms, 2.0);
  EXPECT_LT(*row.full.time_ms, 8.0);
  // The curves, ascending time, the reference last on both rivals'.
  ASSERT_EQ(n.grid.size(), 4u);
  EXPECT_EQ(n.grid.back().method, "reference");
  EXPECT_DOUBLE_EQ(n.grid.back().error, 0.01);
  ASSERT_EQ(n.full.size(), 2u);
  EXPECT_EQ(n.full.front().solver_divisor, 2);
  EXPECT_TRUE(n.grid_monotone);
}

TEST(EqualErrorTable, SaysWhichInputIsMissing) {
  FidelityResult r = pass_with_curves();
  std::erase_if(r.cases, [](const FidelityCase& c) { return c.subject.method == "uniform_grid"; });
  const std::vector<EqualErrorNet> nets = equal_error_table(r);
  ASSERT_EQ(nets.size(), 1u);
  EXPECT_TRUE(nets[0].rows.empty());
  EXPECT_NE(nets[0].missing.find("fidelity.curves.budgets"), std::string::npos) << nets[0].missing;
  r.floors[0].reference_block_step_ms.clear();
  EXPECT_NE(equal_error_table(r)[0].missing.find("not timed"), std::string::npos);
}

TEST(EqualErrorTable, APassWithoutCurvesHasNoTable) {
  FidelityResult r = pass_with_curves();
  std::erase_if(r.cases, [](const FidelityCase& c) { return c.subject.method == "full_resolution"; });
  EXPECT_TRUE(equal_error_table(r).empty());
}

}  // namespace
}  // namespace tcsb
