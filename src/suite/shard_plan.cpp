#include "suite/shard_plan.h"

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

}  // namespace

std::optional<ShardIndex> parse_shard_index(std::string_view text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  const std::optional<int> k = whole_number(text.substr(0, slash)), n = whole_number(text.substr(slash + 1));
  if (!k || !n || *n < 1 || *n > kMaxShards || *k < 1 || *k > *n) return std::nullopt;
  return ShardIndex{*k, *n};
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
  const std::size_t nets = suite.nets.size(), units = configuration_count(suite) * nets;
  std::vector<std::size_t> order(units);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<double> cost(units);
  const std::vector<Suite> configurations = configuration_suites(suite);
  for (std::size_t c = 0; c < configurations.size(); ++c) {
    // A configuration's steps scale its cost; the factor is exactly 1 without axes, so the split is as before.
    const double scale =
        static_cast<double>(steps_per_repetition(configurations[c])) / static_cast<double>(steps_per_repetition(suite));
    for (std::size_t i = 0; i < nets; ++i) cost[c * nets + i] = net_cost_estimate(suite, i) * scale;
  }
  // Longest processing time first: a greedy split within 4/3 of the best possible makespan.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  std::vector<double> load(static_cast<std::size_t>(shard.n), 0.0);
  std::vector<bool> mine(units, false);
  for (const std::size_t unit : order) {
    const std::size_t lightest =
        static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());  // first of equals
    load[lightest] += cost[unit];
    mine[unit] = lightest + 1 == static_cast<std::size_t>(shard.k);
  }
  return mine;
}

}  // namespace tcsb
