// The claims table on the console: interval columns appear only when some claim has an interval.
#include "report/claims_console.h"

#include <gtest/gtest.h>

#include <sstream>

namespace tcsb {
namespace {

TEST(ClaimsConsole, WithoutIntervalsTheTableHasNoIntervalColumns) {
  std::ostringstream out;
  print_claims("Claims:", {check_claim("speed", "", Comparison::kAtMost, 0.4, 0.0, 0.25)}, out);
  EXPECT_NE(out.str().find("speed"), std::string::npos);
  EXPECT_NE(out.str().find("pass"), std::string::npos);
  EXPECT_EQ(out.str().find("interval"), std::string::npos);
  EXPECT_EQ(out.str().find("look"), std::string::npos);
}

/// The line of `out` that mentions `id`.
std::string line_of(const std::string& out, const std::string& id) {
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line))
    if (line.find(id) != std::string::npos) return line;
  return "";
}

TEST(ClaimsConsole, IntervalsAndTheThreeVerdicts) {
  Claim decided_pass = check_claim("speed", "", Comparison::kAtMost, 0.4, 0.0, 0.25, Evidence::kRepeated);
  decided_pass.interval = Interval{0.2, 0.3};
  Claim coin_flip = check_claim("linear", "", Comparison::kAtLeast, 0.98, 0.0, 0.97, Evidence::kRepeated);
  coin_flip.interval = Interval{0.92, 0.995};
  Claim decided_fail = check_claim("slow", "", Comparison::kAtMost, 0.4, 0.0, 0.5, Evidence::kRepeated);
  decided_fail.interval = Interval{0.45, 0.55};
  const Claim no_interval = check_claim("wall", "", Comparison::kAtMost, 120.0, 0.0, 60.0);
  const Claim same = check_claim("same", "", Comparison::kWithin, 1.0, 0.03, 1.0, Evidence::kRepeated);
  std::ostringstream out;
  print_claims("Claims:", {decided_pass, coin_flip, decided_fail, no_interval, same}, out);
  EXPECT_NE(out.str().find("95% interval"), std::string::npos);
  EXPECT_NE(line_of(out.str(), "speed").find("0.2 - 0.3  pass"), std::string::npos) << out.str();
  EXPECT_NE(line_of(out.str(), "linear").find("0.92 - 0.995  undecided"), std::string::npos) << out.str();
  EXPECT_NE(line_of(out.str(), "slow").find("0.45 - 0.55  FAIL"), std::string::npos) << out.str();
  EXPECT_NE(line_of(out.str(), "wall").find("-  pass"), std::string::npos) << out.str();
  // An equivalence claim shows its band; without an interval a repeated claim is undecided.
  EXPECT_NE(line_of(out.str(), "same").find("0.97 - 1.03"), std::string::npos) << out.str();
  EXPECT_NE(line_of(out.str(), "same").find("undecided"), std::string::npos) << out.str();
}

TEST(ClaimsConsole, TrackedClaimsShowTheirLookAndRepetitions) {
  TrackedClaim t;
  t.claim = check_claim("speed", "", Comparison::kAtMost, 0.4, 0.0, 0.25, Evidence::kRepeated);
  t.claim.interval = Interval{0.2, 0.3};
  t.look = 2;
  t.repetitions = 10;
  TrackedClaim exact;
  exact.claim = check_claim("wall", "", Comparison::kAtMost, 120.0, 0.0, 60.0);
  std::ostringstream out;
  print_claims("Claims:", std::vector<TrackedClaim>{t, exact}, out);
  EXPECT_NE(out.str().find("look"), std::string::npos);
  EXPECT_NE(line_of(out.str(), "speed").find("pass        2    10"), std::string::npos) << out.str();
  EXPECT_NE(line_of(out.str(), "wall").find("pass        -     -"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace tcsb
