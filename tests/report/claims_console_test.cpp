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
  EXPECT_EQ(out.str().find("beyond noise"), std::string::npos);
}

TEST(ClaimsConsole, IntervalsAndWhetherTheVerdictIsBeyondNoise) {
  Claim decided_pass = check_claim("speed", "", Comparison::kAtMost, 0.4, 0.0, 0.25);
  decided_pass.interval = Interval{0.2, 0.3};
  Claim coin_flip = check_claim("linear", "", Comparison::kAtLeast, 0.98, 0.0, 0.97);
  coin_flip.interval = Interval{0.92, 0.995};
  const Claim no_interval = check_claim("wall", "", Comparison::kAtMost, 120.0, 0.0, 60.0);
  std::ostringstream out;
  print_claims("Claims:", {decided_pass, coin_flip, no_interval}, out);
  std::istringstream lines(out.str());
  std::string line, speed, linear, wall;
  while (std::getline(lines, line)) {
    if (line.find("speed") != std::string::npos) speed = line;
    if (line.find("linear") != std::string::npos) linear = line;
    if (line.find("wall") != std::string::npos) wall = line;
  }
  EXPECT_NE(out.str().find("95% interval"), std::string::npos);
  EXPECT_NE(speed.find("0.2 - 0.3"), std::string::npos) << speed;
  EXPECT_NE(speed.find("pass     yes"), std::string::npos) << speed;
  EXPECT_NE(linear.find("0.92 - 0.995"), std::string::npos) << linear;
  EXPECT_NE(linear.find("FAIL     no"), std::string::npos) << linear;
  EXPECT_NE(wall.find("pass     -"), std::string::npos) << wall;
}

}  // namespace
}  // namespace tcsb
