// Which shard of a split a process runs: the value a shard's result records and its suite's run filters come
// from. How a suite is split into shards, and how shards are merged, is src/sweep/'s (sweep/shard_plan.h).
#pragma once

#include <optional>
#include <string_view>

namespace tcsb {

/// What a suite is split by.
enum class ShardSplit {
  /// Whole repetitions of a net: every case of the net in that repetition, side by side as unsharded. The largest
  /// net's repetitions spread over the shards.
  kRepetitions,
  /// Whole nets (with axes: one configuration's net): every case and every repetition of the net.
  kNets,
};

/// Shard k of n (1-based: 1 <= k <= n), split by `split`.
struct ShardIndex {
  int k = 1;
  int n = 1;
  ShardSplit split = ShardSplit::kRepetitions;
  bool operator==(const ShardIndex&) const = default;
};

/// The split's stable name: "repetitions" or "nets".
inline const char* split_name(ShardSplit split) { return split == ShardSplit::kNets ? "nets" : "repetitions"; }

/// The split named `name` ("repetitions" or "nets"); nullopt for any other text.
inline std::optional<ShardSplit> parse_split(std::string_view name) {
  for (const ShardSplit s : {ShardSplit::kRepetitions, ShardSplit::kNets})
    if (name == split_name(s)) return s;
  return std::nullopt;
}

/// The largest shard count accepted (a bound against typing errors; far more than any suite has repetitions).
inline constexpr int kMaxShards = 100000;

}  // namespace tcsb
