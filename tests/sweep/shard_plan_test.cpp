// Shard indices and the split of a suite's repetitions, or nets, into shards.
#include "sweep/shard_plan.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace tcsb {
namespace {

const std::filesystem::path kSourceDir = TCSB_SOURCE_DIR;

Suite suite_of_widths(const std::vector<int>& widths) {
  Suite s;
  for (const int w : widths) {
    NetSpec n;
    n.name = "n";
    n.name += std::to_string(w);
    n.width = n.height = w;
    s.nets.push_back(n);
  }
  s.methods = {Method::kPlain, Method::kTcsb};
  s.compression = {1.0, 0.3};
  return s;
}

TEST(ShardIndex, ParsesKOfN) {
  EXPECT_EQ(parse_shard_index("1/1"), (ShardIndex{1, 1}));
  EXPECT_EQ(parse_shard_index("3/7"), (ShardIndex{3, 7}));
  EXPECT_EQ(shard_text({3, 7}), "3/7");
}

TEST(ShardIndex, RefusesAnythingElse) {
  for (const char* bad : {"", "/", "1", "1/", "/3", "0/3", "4/3", "1/0", "-1/3", "+1/3", "1/+3", " 1/3", "1/3 ", "1//3",
                          "a/3", "1/3x", "1.0/3", "1/100001", "99999999999/3"}) {
    EXPECT_FALSE(parse_shard_index(bad).has_value()) << bad;
  }
}

TEST(ShardPlan, EveryNetIsInExactlyOneShard) {
  const Suite s = suite_of_widths({9, 33, 17, 65, 17, 129, 9});
  for (int n = 1; n <= 10; ++n) {
    std::vector<int> owners(s.nets.size(), 0);
    for (int k = 1; k <= n; ++k) {
      const std::vector<bool> mine = shard_units(s, {k, n});
      ASSERT_EQ(mine.size(), s.nets.size());
      for (std::size_t i = 0; i < mine.size(); ++i) owners[i] += mine[i];
    }
    for (std::size_t i = 0; i < owners.size(); ++i) EXPECT_EQ(owners[i], 1) << "net " << i << ", n = " << n;
  }
}

TEST(ShardPlan, OneShardRunsEverything) {
  const Suite s = suite_of_widths({9, 33, 17});
  EXPECT_EQ(shard_units(s, {1, 1}), std::vector<bool>(3, true));
}

TEST(ShardPlan, MoreShardsThanNetsLeavesTheLastOnesEmpty) {
  const Suite s = suite_of_widths({9, 33, 17});
  EXPECT_EQ(shard_units(s, {1, 5}), (std::vector<bool>{false, true, false}));  // the largest first
  EXPECT_EQ(shard_units(s, {2, 5}), (std::vector<bool>{false, false, true}));
  EXPECT_EQ(shard_units(s, {3, 5}), (std::vector<bool>{true, false, false}));
  EXPECT_EQ(shard_units(s, {4, 5}), std::vector<bool>(3, false));
  EXPECT_EQ(shard_units(s, {5, 5}), std::vector<bool>(3, false));
}

TEST(ShardPlan, BalancesByEstimatedCostLargestFirst) {
  // Costs 100, 60, 50, 40, 10 (node counts), each in turn to the lightest shard so far.
  Suite s = suite_of_widths({10, 2, 2, 2, 2});
  s.nets[1].width = 6;  // 60 nodes
  s.nets[1].height = 10;
  s.nets[2].width = 5;  // 50
  s.nets[2].height = 10;
  s.nets[3].width = 4;  // 40
  s.nets[3].height = 10;
  s.nets[4].width = 1;  // 10
  s.nets[4].height = 10;
  // 100 -> 1; 60 -> 2; 50 -> 2 (60 < 100); 40 -> 1 (100 < 110); 10 -> 2 (110 < 140): 140 and 120.
  EXPECT_EQ(shard_units(s, {1, 2}), (std::vector<bool>{true, false, false, true, false}));
  EXPECT_EQ(shard_units(s, {2, 2}), (std::vector<bool>{false, true, true, false, true}));
}

TEST(ShardPlan, TcsbCasesWeighByTheirBudget) {
  Suite s = suite_of_widths({10});
  s.compression = {1.0, 0.3};
  EXPECT_DOUBLE_EQ(net_cost_estimate(s, 0), 100.0 * (1 + 1.0 + 0.3));
}

TEST(ShardPlan, WithAxesTheUnitIsAConfigurationsNetWeightedByItsSteps) {
  Suite s = suite_of_widths({10, 10});
  s.steps = 10;
  s.warmup_steps = 0;
  s.axes = {{"steps", {10, 30}}};
  s.configurations = {{{0}, "steps=10"}, {{1}, "steps=30"}};
  // Units (configuration x 2 + net) cost 230, 230, 690, 690: the two of 30 steps first, one to each shard.
  EXPECT_EQ(shard_units(s, {1, 2}), (std::vector<bool>{true, false, true, false}));
  EXPECT_EQ(shard_units(s, {2, 2}), (std::vector<bool>{false, true, false, true}));
  for (int n = 1; n <= 5; ++n) {
    std::vector<int> owners(4, 0);
    for (int k = 1; k <= n; ++k) {
      const std::vector<bool> mine = shard_units(s, {k, n});
      ASSERT_EQ(mine.size(), 4u);
      for (std::size_t u = 0; u < 4; ++u) owners[u] += mine[u] ? 1 : 0;
    }
    EXPECT_EQ(owners, std::vector<int>(4, 1)) << n << " shards";
  }
}

TEST(ShardPlan, TheScalingSuiteInFourShardsGivesTheLargestNetAShardOfItsOwn) {
  const Suite s = parse_suite(kSourceDir / "suites" / "scaling.json");
  ASSERT_EQ(s.nets.size(), 6u);
  const std::size_t largest = 5;  // n1025
  ASSERT_EQ(s.nets[largest].name, "n1025");
  EXPECT_EQ(shard_units(s, {1, 4}), (std::vector<bool>{false, false, false, false, false, true}));
  EXPECT_EQ(shard_units(s, {2, 4}), (std::vector<bool>{false, false, false, false, true, false}));
  EXPECT_EQ(shard_units(s, {3, 4}), (std::vector<bool>{false, false, false, true, false, false}));
  EXPECT_EQ(shard_units(s, {4, 4}), (std::vector<bool>{true, true, true, false, false, false}));
}

TEST(ShardIndex, CarriesItsSplit) {
  EXPECT_EQ(parse_shard_index("2/3")->split, ShardSplit::kRepetitions);  // the default
  EXPECT_EQ(parse_shard_index("2/3", ShardSplit::kNets), (ShardIndex{2, 3, ShardSplit::kNets}));
  EXPECT_EQ(parse_split("repetitions"), ShardSplit::kRepetitions);
  EXPECT_EQ(parse_split("nets"), ShardSplit::kNets);
  EXPECT_FALSE(parse_split("net").has_value());
  EXPECT_FALSE(parse_split("").has_value());
  EXPECT_STREQ(split_name(ShardSplit::kNets), "nets");
}

/// Splits `s` by repetition into 1..max_shards shards and checks every repetition of every net lands in exactly one;
/// `check(shard, its repetitions)` may look at each shard's set too.
template <class Check>
void expect_every_repetition_once(const Suite& s, int max_shards, Check check) {
  const std::size_t repetitions = static_cast<std::size_t>(s.repetitions);
  for (int n = 1; n <= max_shards; ++n) {
    std::vector<int> owners(s.nets.size() * repetitions, 0);
    for (int k = 1; k <= n; ++k) {
      const std::vector<bool> mine = shard_repetitions(s, {k, n});
      ASSERT_EQ(mine.size(), owners.size());
      for (std::size_t i = 0; i < mine.size(); ++i) owners[i] += mine[i];
      check(ShardIndex{k, n}, mine);
    }
    EXPECT_EQ(owners, std::vector<int>(owners.size(), 1)) << n << " shards";
  }
}

TEST(ShardPlan, EveryRepetitionOfEveryNetIsInExactlyOneShard) {
  Suite s = suite_of_widths({9, 33, 17, 65});
  s.repetitions = 3;
  expect_every_repetition_once(s, 14, [](const ShardIndex&, const std::vector<bool>&) {});
}

TEST(ShardPlan, AcrossNetsAShardTakesWholeRepetitionsOfEveryNet) {
  Suite s = suite_of_widths({9, 33, 17, 65});
  s.repetitions = 5;
  s.interleave_steps = 8;
  s.interleave_across_nets = true;  // a repetition's nets run together, so they must stay in one process
  expect_every_repetition_once(s, 7, [&](const ShardIndex& shard, const std::vector<bool>& mine) {
    for (std::size_t r = 0; r < 5; ++r)
      for (std::size_t net = 1; net < s.nets.size(); ++net)
        EXPECT_EQ(mine[net * 5 + r], mine[r])
            << "repetition " << r << ", net " << net << ", shard " << shard_text(shard);
  });
}

TEST(ShardPlan, RestrictingToAShardSetsItsUnitsAndRepetitions) {
  Suite s = suite_of_widths({9, 33, 17});
  s.repetitions = 2;
  for (int k = 1; k <= 4; ++k) {
    Suite by_repetition = s, by_net = s;
    restrict_to_shard(by_repetition, {k, 4, ShardSplit::kRepetitions});
    restrict_to_shard(by_net, {k, 4, ShardSplit::kNets});
    EXPECT_EQ(by_net.run_units, shard_units(s, {k, 4}));
    EXPECT_TRUE(by_net.run_repetitions.empty());  // every repetition of its nets
    EXPECT_EQ(by_repetition.run_repetitions, shard_repetitions(s, {k, 4}));
    for (std::size_t net = 0; net < 3; ++net) {
      const bool any = runs_repetition(by_repetition, 0, net, 0) || runs_repetition(by_repetition, 0, net, 1);
      EXPECT_EQ(runs_unit(by_repetition, 0, net), any) << "net " << net << ", shard " << k;
      EXPECT_EQ(runs_fidelity_of(by_repetition, net), runs_repetition(by_repetition, 0, net, 0));
    }
  }
}

TEST(ShardPlan, TheScalingSuiteSplitByRepetitionSpreadsItsLargestNet) {
  // The 1025^2 net holds three quarters of the work: split by net it is one shard's alone; split by repetition each
  // of four shards runs one of its four repetitions, the smaller nets' filling in around them.
  Suite s = parse_suite(kSourceDir / "suites" / "scaling.json");
  s.repetitions = 4;
  const std::size_t largest = 5;
  ASSERT_EQ(s.nets[largest].name, "n1025");
  std::vector<int> repetitions_of_largest;
  for (int k = 1; k <= 4; ++k) {
    const std::vector<bool> mine = shard_repetitions(s, {k, 4});
    int count = 0;
    for (std::size_t r = 0; r < 4; ++r) count += mine[largest * 4 + r];
    repetitions_of_largest.push_back(count);
  }
  EXPECT_EQ(repetitions_of_largest, (std::vector<int>{1, 1, 1, 1}));
}

}  // namespace
}  // namespace tcsb
