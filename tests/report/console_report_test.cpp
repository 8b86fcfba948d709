// The console report: aligned columns, every section present, "-" for what was not measured.
#include "report/console_report.h"

#include <gtest/gtest.h>

#include <sstream>

#include "render_run.h"
#include "report/text_table.h"
#include "synthetic_run.h"

namespace tcsb {
namespace {

using testing::diverge;
using testing::make_case;
using testing::synthetic_suite;

TEST(TextTable, PadsColumnsToTheWidestCell) {
  TextTable t({{"name", TextTable::Align::kLeft}, {"ms"}});
  t.add_row({"a", "1.5"});
  t.add_row({"longer", "10.25"});
  std::ostringstream out;
  t.print(out, 0);
  EXPECT_EQ(out.str(), "name       ms\n"
                       "------  -----\n"
                       "a         1.5\n"
                       "longer  10.25\n");
}

TEST(TextTable, NumberFormatting) {
  EXPECT_EQ(fixed(1.23456, 2), "1.23");
  EXPECT_EQ(fixed(std::nullopt, 2), "-");
  EXPECT_EQ(fixed(std::numeric_limits<double>::quiet_NaN(), 2), "-");
  EXPECT_EQ(general(0.000123456, 3), "0.000123");
}

TEST(ConsoleReport, HasEverySection) {
  RunResult r;
  r.suite = synthetic_suite(2);
  r.suite.compression = {0.5};
  r.cases = {make_case(r.suite, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0),
             make_case(r.suite, 0, Method::kTcsb, 0.5, 50, 100, 3, 0.5),
             make_case(r.suite, 1, Method::kPlain, std::nullopt, 400, 800, 0, 3.0),
             make_case(r.suite, 1, Method::kTcsb, 0.5, 200, 400, 3, 1.5)};
  diverge(r.cases[3], 5);
  std::ostringstream out;
  testing::print_console_report_of(r, out);
  const std::string text = out.str();
  for (const char* part : {"n0/plain", "n1/tcsb@0.5", "diverged", "Table 1", "Table 2", "partial", "50%",
                           "Step time vs nodes", "Operation time vs nodes", "refine", "end-coarse"}) {
    EXPECT_NE(text.find(part), std::string::npos) << part;
  }
  EXPECT_EQ(text.find("nan"), std::string::npos);
}

TEST(ConsoleReport, TheVsEqualColumnAppearsOnlyWithPlainEqual) {
  RunResult r;
  r.suite = synthetic_suite(1);
  r.suite.compression = {0.5};
  r.cases = {make_case(r.suite, 0, Method::kPlain, std::nullopt, 100, 200, 0, 1.0, {1.0, 1.0}),
             make_case(r.suite, 0, Method::kTcsb, 0.5, 50, 100, 3, 0.5, {0.5, 0.66})};
  std::ostringstream without;
  testing::print_console_report_of(r, without);
  EXPECT_EQ(without.str().find("vs equal"), std::string::npos);
  r.suite.methods.push_back(Method::kPlainEqual);
  r.cases.push_back(make_case(r.suite, 0, Method::kPlainEqual, 0.5, 50, 90, 0, 0.5, {0.5, 0.6}));
  std::ostringstream with;
  testing::print_console_report_of(r, with);
  const std::string text = with.str();
  ASSERT_NE(text.find("vs equal"), std::string::npos);
  // The TC-SB row: vs plain 0.580 (median of 0.5 and 0.66), vs equal 1.050 (median of 1.0 and 1.1), 2 of 2 reps.
  const std::size_t row = text.find("n0/tcsb@0.5");
  ASSERT_NE(row, std::string::npos);
  const std::string line = text.substr(row, text.find('\n', row) - row);
  EXPECT_NE(line.find("0.580  "), std::string::npos) << line;
  EXPECT_NE(line.find("1.050  "), std::string::npos) << line;
}

}  // namespace
}  // namespace tcsb
