// The pairing rule: a case's base is the plain (or, for TC-SB with a budget, the plain_equal of that budget) case of
// the same place, and repetitions pair by number, both ok.
#include "base/case_pairing.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace tcsb {
namespace {

struct Case {
  std::string net, configuration;
  PairingRole role;
  std::optional<double> compression;
};

auto key_of(const Case& c) { return PairingKey{std::tie(c.net, c.configuration), c.role, c.compression}; }

const std::vector<Case> kCases = {
    {"n9", "a", PairingRole::kTcsb, 0.5},
    {"n9", "b", PairingRole::kPlain, {}},
    {"n9", "a", PairingRole::kPlainEqual, 0.3},
    {"n9", "a", PairingRole::kPlain, {}},
    {"n9", "a", PairingRole::kPlainEqual, 0.5 + 1e-12},
    {"n17", "a", PairingRole::kPlain, {}},
};

TEST(CasePairing, ThePlainPartnerIsOfTheSameNetAndConfiguration) {
  EXPECT_EQ(plain_partner(kCases, 0, key_of), 3u) << "not the plain case of configuration b";
  EXPECT_EQ(plain_partner(kCases, 5, key_of), 5u);
  EXPECT_EQ(plain_partner(kCases, 99, key_of), std::nullopt);
}

TEST(CasePairing, TheEqualPlainPartnerHasTheSameCompression) {
  EXPECT_EQ(equal_plain_partner(kCases, 0, key_of), 4u) << "0.5 and 0.5 + 1e-12 are one target, 0.3 is not";
  EXPECT_EQ(equal_plain_partner(kCases, 3, key_of), std::nullopt) << "only a TC-SB case has one";
  EXPECT_TRUE(same_compression(0.3, 0.1 * 3));
  EXPECT_FALSE(same_compression(0.3, 0.3 + 2e-9));
}

struct Repetition {
  int repetition;
  std::string status;
};

TEST(CasePairing, RepetitionsPairByNumberBothOk) {
  const std::vector<Repetition> tcsb = {{0, "ok"}, {1, "ok"}, {2, "diverged"}, {3, "ok"}};
  const std::vector<Repetition> plain = {{3, "ok"}, {1, "diverged"}, {0, "ok"}, {2, "ok"}};
  std::vector<std::pair<int, int>> pairs;
  for_each_repetition_pair(tcsb, plain, [&](const Repetition& r, const Repetition& b) {
    pairs.emplace_back(r.repetition, b.repetition);
  });
  EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{0, 0}, {3, 3}}));
}

}  // namespace
}  // namespace tcsb
