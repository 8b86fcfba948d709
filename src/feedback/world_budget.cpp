#include "feedback/world_budget.h"

#include <algorithm>
#include <stdexcept>

#include "feedback/controller.h"
#include "softbody/tc_softbody.h"

namespace tcsb {

namespace {

/// What a body would hold at threshold tau.
int share_at(const BudgetDemand& d, double tau, double half_gap) {
  const auto above = std::count_if(d.refine.begin(), d.refine.end(), [&](double p) { return p > tau + half_gap; });
  const auto below = std::count_if(d.coarse.begin(), d.coarse.end(), [&](double p) { return p < tau - half_gap; });
  const long long nodes = d.nodes + static_cast<long long>(d.nodes_per_operation) * (above - below);
  return static_cast<int>(std::clamp<long long>(nodes, d.fewest, std::max(d.fewest, d.most)));
}

long long total_at(std::span<const BudgetDemand> demands, double tau, double half_gap) {
  long long total = 0;
  for (const BudgetDemand& d : demands) total += share_at(d, tau, half_gap);
  return total;
}

}  // namespace

std::vector<int> split_world_budget(std::span<const BudgetDemand> demands, int world_budget, double hysteresis) {
  if (world_budget < 1) throw std::invalid_argument("split_world_budget: the world budget must be >= 1");
  const double half_gap = 0.5 * std::max(0.0, hysteresis);
  // The total is a step function of tau, non-increasing, changing only where tau +- half_gap meets a priority.
  std::vector<double> steps;
  for (const BudgetDemand& d : demands) {
    for (const double p : d.refine) steps.push_back(p - half_gap);
    for (const double p : d.coarse) steps.push_back(p + half_gap);
  }
  std::sort(steps.begin(), steps.end());
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  // One threshold inside each interval the points cut the line into, lowest first: below them all, between each
  // two, above them all. The totals there do not increase; the first that fits spends the most without exceeding.
  const auto threshold = [&steps](std::size_t k) {
    if (k == 0) return steps.front() - 1.0;
    if (k == steps.size()) return steps.back() + 1.0;
    return 0.5 * (steps[k - 1] + steps[k]);
  };
  double tau = 0;
  if (!steps.empty()) {
    std::size_t lo = 0, hi = steps.size();  // at hi everything ranked is coarsened: the coarsest reachable
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (total_at(demands, threshold(mid), half_gap) <= world_budget)
        hi = mid;
      else
        lo = mid + 1;
    }
    tau = threshold(lo);
  }
  std::vector<int> shares;
  shares.reserve(demands.size());
  for (const BudgetDemand& d : demands) shares.push_back(share_at(d, tau, half_gap));
  return shares;
}

std::vector<int> limit_growth_to_free_nodes(std::span<const BudgetDemand> demands, std::vector<int> shares,
                                            int world_budget) {
  long long held = 0, growth = 0;
  for (std::size_t i = 0; i < demands.size(); ++i) {
    const long long simulated = std::max(demands[i].nodes, demands[i].simulated);
    held += std::max<long long>(shares[i], simulated);
    growth += std::max<long long>(0, shares[i] - simulated);
  }
  const long long over = held - world_budget;
  if (over <= 0 || growth == 0) return shares;
  const long long allowed = std::max<long long>(0, growth - over);
  for (std::size_t i = 0; i < demands.size(); ++i) {
    const long long simulated = std::max(demands[i].nodes, demands[i].simulated);
    if (shares[i] > simulated) shares[i] = static_cast<int>(simulated + (shares[i] - simulated) * allowed / growth);
  }
  return shares;
}

void share_world_budget(std::span<const WorldBudgetMember> members, int world_budget, double hysteresis) {
  std::vector<BudgetDemand> demands(members.size());
  long long reserves = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const TcSoftBody& body = *members[i].body;
    const LodTree& tree = body.tree();
    const int top = tree.level_count() - 1;
    BudgetDemand& d = demands[i];
    d.nodes = body.committed_count();
    d.simulated = body.node_count();
    d.fewest = tree.level_width(top) * tree.level_height(top);
    d.most = static_cast<int>(tree.leaf_count());
    if (members[i].controller) members[i].controller->budget_demand(d);
    reserves += d.reserve;
  }
  const int shared = static_cast<int>(std::max<long long>(1, world_budget - reserves));
  std::vector<int> budgets = split_world_budget(demands, shared, hysteresis);
  for (std::size_t i = 0; i < members.size(); ++i) budgets[i] += demands[i].reserve;
  budgets = limit_growth_to_free_nodes(demands, std::move(budgets), world_budget);
  for (std::size_t i = 0; i < members.size(); ++i)
    if (members[i].controller) members[i].controller->set_budget(std::max(1, budgets[i]));
}

}  // namespace tcsb
