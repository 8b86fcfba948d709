// One-to-one matching by key: pairs only keys that occur exactly once on each side, whatever the order, and returns
// every other key with its occurrences.
#include "gate/one_to_one_match.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

namespace tcsb {
namespace {

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

OneToOneMatch<int> match(const std::vector<int>& base, const std::vector<int>& next) {
  return match_one_to_one<int>(base, next);
}

TEST(OneToOneMatch, PairsByKeyInBaseOrderWhateverThePositions) {
  const OneToOneMatch<int> m = match({0, 1, 2, 3}, {3, 1, 0, 2});
  EXPECT_EQ(m.pairs, (Pairs{{0, 2}, {1, 1}, {2, 3}, {3, 0}}));
  EXPECT_TRUE(m.unmatched.empty());
}

TEST(OneToOneMatch, MissingExtraAndDuplicatedKeysAreUnmatched) {
  // 1 missing from next, 5 extra in next, 2 twice in next, 3 twice in base and once in next, 7 twice on both.
  const OneToOneMatch<int> m = match({0, 1, 2, 3, 3, 7, 7}, {7, 0, 2, 5, 2, 3, 7});
  EXPECT_EQ(m.pairs, (Pairs{{0, 1}}));
  ASSERT_EQ(m.unmatched.size(), 5u);
  const std::vector<std::tuple<int, std::size_t, std::size_t>> expected = {
      {1, 1, 0}, {2, 1, 2}, {3, 2, 1}, {7, 2, 2}, {5, 0, 1}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(m.unmatched[i].key, std::get<0>(expected[i])) << i;
    EXPECT_EQ(m.unmatched[i].base, std::get<1>(expected[i])) << i;
    EXPECT_EQ(m.unmatched[i].next, std::get<2>(expected[i])) << i;
  }
}

TEST(OneToOneMatch, EmptyListsAndStringKeys) {
  EXPECT_TRUE(match({}, {}).pairs.empty());
  EXPECT_TRUE(match({}, {}).unmatched.empty());
  const std::vector<std::string> base = {"n9/plain", "n9/tcsb@0.5"}, next = {"n9/tcsb@0.5"};
  const OneToOneMatch<std::string> m = match_one_to_one<std::string>(base, next);
  EXPECT_EQ(m.pairs, (Pairs{{1, 0}}));
  ASSERT_EQ(m.unmatched.size(), 1u);
  EXPECT_EQ(m.unmatched[0].key, "n9/plain");
}

}  // namespace
}  // namespace tcsb
