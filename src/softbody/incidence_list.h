// IncidenceList: the links touching one node, kept per node so no operation ever searches the link array.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>

namespace tcsb {

/// Fixed-capacity list of link indices, one cache line each. A balanced cut bounds a node's degree: at most two
/// neighbours per side, 8 steady links. While operations blend, a side holds at most 3 links (a neighbour refined:
/// its fading link and its two children's; two finer neighbours coarsened: their two fading links and the parent's),
/// and no operation may begin next to a node that is itself blending, so an active node has at most 12; a refined
/// node has at most 8 fading links and 4 tethers, a coarse's new node 8 arriving links and 4 tethers. Overflowing
/// is therefore a bug, and throws.
class alignas(64) IncidenceList {
 public:
  static constexpr int kCapacity = 12;

  int size() const { return count_; }
  std::int32_t operator[](int i) const { return links_[static_cast<std::size_t>(i)]; }
  const std::int32_t* begin() const { return links_.data(); }
  const std::int32_t* end() const { return links_.data() + count_; }

  void add(std::int32_t link) {
    if (count_ == kCapacity) throw std::logic_error("IncidenceList: node degree exceeds 12");
    links_[static_cast<std::size_t>(count_++)] = link;
  }
  /// Removes `link` (order not kept); returns false if absent.
  bool remove(std::int32_t link) {
    for (int i = 0; i < count_; ++i)
      if (links_[static_cast<std::size_t>(i)] == link) {
        links_[static_cast<std::size_t>(i)] = links_[static_cast<std::size_t>(--count_)];
        return true;
      }
    return false;
  }
  /// Rewrites `from` into `to` (a link moved in the link array); returns false if absent.
  bool replace(std::int32_t from, std::int32_t to) {
    for (int i = 0; i < count_; ++i)
      if (links_[static_cast<std::size_t>(i)] == from) {
        links_[static_cast<std::size_t>(i)] = to;
        return true;
      }
    return false;
  }
  /// Rewrites every entry e into position[e] (the links were permuted).
  template <class Positions>
  void renumber(const Positions& position) {
    for (int i = 0; i < count_; ++i)
      links_[static_cast<std::size_t>(i)] = position[static_cast<std::size_t>(links_[static_cast<std::size_t>(i)])];
  }
  bool contains(std::int32_t link) const {
    for (int i = 0; i < count_; ++i)
      if (links_[static_cast<std::size_t>(i)] == link) return true;
    return false;
  }

 private:
  std::array<std::int32_t, kCapacity> links_{};
  std::int32_t count_ = 0;
};
static_assert(sizeof(IncidenceList) == 64, "an incidence list should fill exactly one cache line");

}  // namespace tcsb
