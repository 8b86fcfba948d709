// Shards: a suite's work split into N parts that separate processes (Slurm array tasks, CI matrix jobs, GNU parallel
// slots) run independently and `tcsb merge` joins (sweep/shard_merge.h). Either split keeps every same-run ratio
// within one process, interleaved as in an unsharded run:
//  - by repetition (the default): a unit is one repetition of a net (with axes: of one configuration's net) — every
//    case of the net in that repetition. A net whose work dominates the suite spreads over the shards.
//  - by net: a unit is a net with all its repetitions; each net is built in one shard only.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "suite/shard_index.h"
#include "suite/suite.h"

namespace tcsb {

/// Parses "K/N" (decimal, 1 <= K <= N <= kMaxShards, nothing else around it) with the split `split`; nullopt
/// otherwise.
std::optional<ShardIndex> parse_shard_index(std::string_view text, ShardSplit split = ShardSplit::kRepetitions);

/// "K/N".
std::string shard_text(const ShardIndex& shard);

/// The estimated cost of a net's cases, for balancing shards: its node count times the number of its cases, a
/// TC-SB case weighted by its budget (it simulates about that fraction of the nodes).
double net_cost_estimate(const Suite& suite, std::size_t net);

/// The split by net: which units shard `shard` runs, indexed like Suite::run_units (configuration x nets + net;
/// without axes, like suite.nets), whatever shard.split says. Deterministic (the same suite and n give the same
/// split on every machine): units are taken in decreasing estimated cost (net_cost_estimate scaled by the
/// configuration's steps; ties: unit order) and each goes to the shard with the least estimated cost so far (ties:
/// the lowest k), so one large net does not share a shard with others while shards stay idle. Every unit is in
/// exactly one of the n shards; with more shards than units some are empty.
std::vector<bool> shard_units(const Suite& suite, const ShardIndex& shard);

/// The split by repetition: which repetitions shard `shard` runs, indexed like Suite::run_repetitions (unit x
/// suite.repetitions + repetition), whatever shard.split says. The same greedy rule as shard_units over (unit,
/// repetition) pairs, a pair costing its unit's cost over the repetitions (ties: unit order, then repetition), so a
/// net's repetitions go round the shards. With Suite::interleave_across_nets the items are whole repetitions (every
/// unit's repetition r in the same shard), as they run together. Every repetition of every unit is in exactly one of
/// the n shards.
std::vector<bool> shard_repetitions(const Suite& suite, const ShardIndex& shard);

/// Restricts `suite` to what shard `shard` runs, by its split: Suite::run_units, and with the split by repetition
/// Suite::run_repetitions (run_units then marks the units with any repetition in the shard). Call it after every
/// setting that changes the cases (compression, repetitions) is applied.
void restrict_to_shard(Suite& suite, const ShardIndex& shard);

}  // namespace tcsb
