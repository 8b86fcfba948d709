// Shards: a suite's work split into N parts that separate processes (Slurm array tasks, CI matrix jobs, GNU parallel
// slots) run independently and `tcsb merge` joins. The unit of the split is the net (with axes: one configuration's
// cases of one net): a unit's cases (plain, TC-SB at every budget, ...) and all their repetitions stay in one shard,
// so every same-run ratio is still measured within one process, under the same machine conditions, interleaved as in
// an unsharded run.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "suite/suite.h"

namespace tcsb {

/// Shard k of n (1-based: 1 <= k <= n).
struct ShardIndex {
  int k = 1;
  int n = 1;
  bool operator==(const ShardIndex&) const = default;
};

/// The largest shard count accepted (a bound against typing errors; far more than any suite has nets).
inline constexpr int kMaxShards = 100000;

/// Parses "K/N" (decimal, 1 <= K <= N <= kMaxShards, nothing else around it); nullopt otherwise.
std::optional<ShardIndex> parse_shard_index(std::string_view text);

/// "K/N".
std::string shard_text(const ShardIndex& shard);

/// The estimated cost of a net's cases, for balancing shards: its node count times the number of its cases, a
/// TC-SB case weighted by its budget (it simulates about that fraction of the nodes).
double net_cost_estimate(const Suite& suite, std::size_t net);

/// Which units shard `shard` runs, indexed like Suite::run_units (configuration x nets + net; without axes, like
/// suite.nets). Deterministic (the same suite and n give the same split on every machine): units are taken in
/// decreasing estimated cost (net_cost_estimate scaled by the configuration's steps; ties: unit order) and each goes
/// to the shard with the least estimated cost so far (ties: the lowest k), so one large net does not share a shard
/// with others while shards stay idle. Every unit is in exactly one of the n shards; with more shards than units
/// some are empty.
std::vector<bool> shard_units(const Suite& suite, const ShardIndex& shard);

}  // namespace tcsb
