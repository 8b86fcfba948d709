#include "sweep/shard_plan.h"

#include <algorithm>
#include <charconv>
#include <numeric>

#include "suite/suite_axes.h"

namespace tcsb {
namespace {

/// A whole decimal number with nothing around it, or nullopt.
std::optional<int> whole_number(std::string_view text) {
  int value = 0;
  if (text.empty() || text.front() == '+' || text.front() == '-') return std::nullopt;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

/// Each unit's estimated cost (configuration x nets + net).
std::vector<double> unit_costs(const Suite& suite) {
  const std::size_t nets = suite.nets.size();
  std::vector<double> cost(configuration_count(suite) * nets);
  const std::vector<Suite> configurations = configuration_suites(suite);
  for (std::size_t c = 0; c < configurations.size(); ++c) {
    // A configuration's steps scale its cost; the factor is exactly 1 without axes, so the split is as before.
    const double scale =
        static_cast<double>(steps_per_repetition(configurations[c])) / static_cast<double>(steps_per_repetition(suite));
    for (std::size_t i = 0; i < nets; ++i) cost[c * nets + i] = net_cost_estimate(suite, i) * scale;
  }
  return cost;
}

/// Longest processing time first, a greedy split within 4/3 of the best possible makespan: items in decreasing
/// cost (ties: item order), each to the shard with the least cost so far (ties: the lowest k). Whether each item is
/// shard k's.
std::vector<bool> greedy_split(const std::vector<double>& cost, const ShardIndex& shard) {
  std::vector<std::size_t> order(cost.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  std::vector<double> load(static_cast<std::size_t>(shard.n), 0.0);
  std::vector<bool> mine(cost.size(), false);
  for (const std::size_t item : order) {
    const std::size_t lightest =
        static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());  // first of equals
    load[lightest] += cost[item];
    mine[item] = lightest + 1 == static_cast<std::size_t>(shard.k);
  }
  return mine;
}

}  // namespace

std::optional<ShardIndex> parse_shard_index(std::string_view text, ShardSplit split) {
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  const std::optional<int> k = whole_number(text.substr(0, slash)), n = whole_number(text.substr(slash + 1));
  if (!k || !n || *n < 1 || *n > kMaxShards || *k < 1 || *k > *n) return std::nullopt;
  return ShardIndex{*k, *n, split};
}

std::string shard_text(const ShardIndex& shard) { return std::to_string(shard.k) + "/" + std::to_string(shard.n); }

double net_cost_estimate(const Suite& suite, std::size_t net) {
  double cases = 0;
  for (const Method m : suite.methods) {
    if (m != Method::kTcsb) {
      cases += 1;
      continue;
    }
    for (const double c : suite.compression) cases += c;
  }
  return static_cast<double>(suite.nets[net].node_count()) * cases;
}

std::vector<bool> shard_units(const Suite& suite, const ShardIndex& shard) {
  return greedy_split(unit_costs(suite), shard);
}

std::vector<bool> shard_repetitions(const Suite& suite, const ShardIndex& shard) {
  const std::vector<double> units = unit_costs(suite);
  const auto repetitions = static_cast<std::size_t>(std::max(suite.repetitions, 0));
  if (suite.interleave_across_nets) {
    // Every net's cases of a repetition take turns together: the repetition is what a shard takes, whole, so the
    // nets of each repetition stay in one process as unsharded (and the bootstrap can still draw them together).
    const double each = std::accumulate(units.begin(), units.end(), 0.0) / static_cast<double>(repetitions);
    const std::vector<bool> mine_of_repetition = greedy_split(std::vector<double>(repetitions, each), shard);
    std::vector<bool> mine;
    mine.reserve(units.size() * repetitions);
    for (std::size_t u = 0; u < units.size(); ++u)
      mine.insert(mine.end(), mine_of_repetition.begin(), mine_of_repetition.end());
    return mine;
  }
  std::vector<double> cost;
  cost.reserve(units.size() * repetitions);
  for (const double unit : units)
    for (std::size_t r = 0; r < repetitions; ++r) cost.push_back(unit / static_cast<double>(repetitions));
  return greedy_split(cost, shard);
}

void restrict_to_shard(Suite& suite, const ShardIndex& shard) {
  if (shard.split == ShardSplit::kNets) {
    suite.run_units = shard_units(suite, shard);
    suite.run_repetitions.clear();
    return;
  }
  suite.run_repetitions = shard_repetitions(suite, shard);
  const auto repetitions = static_cast<std::size_t>(std::max(suite.repetitions, 0));
  suite.run_units.assign(configuration_count(suite) * suite.nets.size(), false);
  for (std::size_t u = 0; u < suite.run_units.size(); ++u)
    for (std::size_t r = 0; r < repetitions; ++r)
      if (suite.run_repetitions[u * repetitions + r]) suite.run_units[u] = true;
}

}  // namespace tcsb
