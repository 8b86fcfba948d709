// The world budget's split: one threshold for every body, shares that add up to the budget, the far body's nodes to
// the near one.
#include "feedback/world_budget.h"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>
#include <vector>

namespace tcsb {
namespace {

BudgetDemand demand(int nodes, std::vector<double> refine, std::vector<double> coarse) {
  BudgetDemand d;
  d.nodes = nodes;
  d.fewest = 4;
  d.most = 1000;
  d.refine = std::move(refine);
  d.coarse = std::move(coarse);
  return d;
}

int total(const std::vector<int>& shares) { return std::accumulate(shares.begin(), shares.end(), 0); }

TEST(WorldBudget, MovesNodesFromWhatMattersLittleToWhatMattersMost) {
  // The near body ranks refines at 5 and 4, the far one would coarsen at 0.1 and 0.2: at a budget of their sum the
  // far body gives two blocks' worth to the near one.
  const std::vector<BudgetDemand> d{demand(100, {5, 4}, {3, 3.5}), demand(100, {0.3}, {0.1, 0.2})};
  const std::vector<int> shares = split_world_budget(d, 200, 0.0);
  EXPECT_EQ(shares[0], 106);
  EXPECT_EQ(shares[1], 94);
  EXPECT_EQ(total(shares), 200);
}

TEST(WorldBudget, SpendsWhatIsFreeAndCoarsensWhatDoesNotFit) {
  const std::vector<BudgetDemand> d{demand(100, {5, 4}, {3}), demand(100, {2}, {1})};
  EXPECT_EQ(split_world_budget(d, 1000, 0.0), (std::vector<int>{106, 103}));  // room for every refine
  // 180 nodes: everything ranked coarsened still holds 194, the coarsest the ranked candidates reach this step.
  EXPECT_EQ(split_world_budget(d, 180, 0.0), (std::vector<int>{97, 97}));
}

TEST(WorldBudget, TheHysteresisKeepsCloseRanksFromTrading) {
  // A refine at 1.0 in one body, a coarse at 0.95 in the other: traded without hysteresis, kept with 0.1.
  const std::vector<BudgetDemand> d{demand(100, {1.0}, {0.99}), demand(100, {0.9}, {0.95})};
  EXPECT_EQ(split_world_budget(d, 200, 0.0), (std::vector<int>{103, 97}));
  EXPECT_EQ(split_world_budget(d, 200, 0.1), (std::vector<int>{100, 100}));
}

TEST(WorldBudget, SharesStayWithinEachBodysCuts) {
  BudgetDemand small = demand(10, {9, 8, 7}, {});
  small.most = 16;
  BudgetDemand coarse = demand(5, {}, {0.1, 0.2});
  coarse.fewest = 4;
  const std::vector<int> shares = split_world_budget(std::vector<BudgetDemand>{small, coarse}, 100, 0.0);
  EXPECT_EQ(shares[0], 16);
  EXPECT_EQ(shares[1], 5);  // nothing to coarsen for: the budget is not short
  EXPECT_EQ(split_world_budget(std::vector<BudgetDemand>{coarse}, 1, 0.0)[0], 4);
}

TEST(WorldBudget, WithoutCandidatesEachBodyKeepsWhatItHas) {
  const std::vector<BudgetDemand> d{demand(50, {}, {}), demand(70, {}, {})};
  EXPECT_EQ(split_world_budget(d, 100, 0.0), (std::vector<int>{50, 70}));
  EXPECT_TRUE(split_world_budget(std::vector<BudgetDemand>{}, 100, 0.0).empty());
  EXPECT_THROW(split_world_budget(d, 0, 0.0), std::invalid_argument);
}

TEST(WorldBudget, ABodyGrowsOnlyIntoWhatAnotherHasReleased) {
  // The far body's share fell from 100 to 70 but it still simulates 100 (its coarsening blends): of the near body's
  // 30 more only what the world has free may come now.
  std::vector<BudgetDemand> d{demand(100, {}, {}), demand(100, {}, {})};
  d[1].simulated = 100;
  EXPECT_EQ(limit_growth_to_free_nodes(d, {130, 70}, 200), (std::vector<int>{100, 70}));
  EXPECT_EQ(limit_growth_to_free_nodes(d, {130, 70}, 210), (std::vector<int>{110, 70}));
  // Released: the far body simulates its 70.
  d[1].nodes = d[1].simulated = 70;
  EXPECT_EQ(limit_growth_to_free_nodes(d, {130, 70}, 200), (std::vector<int>{130, 70}));
}

TEST(WorldBudget, GrowthIsCutInProportionAndFallingSharesAreKept) {
  std::vector<BudgetDemand> d{demand(100, {}, {}), demand(100, {}, {}), demand(100, {}, {})};
  d[2].simulated = 112;  // blends in flight: 12 more Bullet nodes than committed
  // Held: 120 + 140 + 112 = 372 against 320, over by 52 of a growth of 60: 8 remain, shared 20 : 40.
  const std::vector<int> shares = limit_growth_to_free_nodes(d, {120, 140, 60}, 320);
  EXPECT_EQ(shares, (std::vector<int>{102, 105, 60}));
  EXPECT_LE(shares[0] + shares[1] + 112, 320);
}

}  // namespace
}  // namespace tcsb
