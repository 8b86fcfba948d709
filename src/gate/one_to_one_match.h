// Matching two lists one to one by key (cases by label, repetitions by number), the way a gate must: a key pairs
// only when it occurs exactly once on each side, and every other key — absent from a side, or duplicated on
// either — is returned as unmatched, never silently dropped. Positions do not matter, so a reordered list still
// pairs every key, and a partial match can never pass for a complete one. Pure, header-only (a template over the
// key type).
#pragma once

#include <cstddef>
#include <map>
#include <span>
#include <utility>
#include <vector>

namespace tcsb {

/// How often one key occurs in each list.
template <typename Key>
struct KeyOccurrences {
  Key key;               ///< the key
  std::size_t base = 0;  ///< occurrences in the base list
  std::size_t next = 0;  ///< occurrences in the new list
};

/// Two lists matched by key.
template <typename Key>
struct OneToOneMatch {
  /// (base index, new index) of every key that occurs exactly once in each list, in base order.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  /// Every other key, in order of first occurrence (the base list first, then the new one).
  std::vector<KeyOccurrences<Key>> unmatched;
};

/// Matches `base` with `next` by key; see OneToOneMatch. Every key of either list is in exactly one of the pairs
/// or the unmatched, so pairs.size() == base.size() == next.size() if and only if unmatched is empty.
template <typename Key>
OneToOneMatch<Key> match_one_to_one(std::span<const Key> base, std::span<const Key> next) {
  struct Seen {
    std::size_t base = 0, next = 0;              // occurrences
    std::size_t base_index = 0, next_index = 0;  // first occurrence
  };
  std::map<Key, Seen> seen;
  std::vector<const Key*> order;  // first occurrence, base list first
  const auto count = [&](std::span<const Key> keys, std::size_t Seen::*occurrences, std::size_t Seen::*first) {
    for (std::size_t i = 0; i < keys.size(); ++i) {
      auto [it, fresh] = seen.try_emplace(keys[i]);
      if (fresh) order.push_back(&it->first);
      if ((it->second.*occurrences)++ == 0) it->second.*first = i;
    }
  };
  count(base, &Seen::base, &Seen::base_index);
  count(next, &Seen::next, &Seen::next_index);

  OneToOneMatch<Key> out;
  for (const Key* key : order) {
    const Seen& s = seen.at(*key);
    if (s.base == 1 && s.next == 1) {
      out.pairs.emplace_back(s.base_index, s.next_index);
    } else {
      out.unmatched.push_back({*key, s.base, s.next});
    }
  }
  return out;
}

}  // namespace tcsb
