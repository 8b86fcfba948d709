// TcSoftBody::restore_order(): Bullet's node and link arrays back in a plain body's spatial order; and
// rebuild_node_dbvt(): the node DBVT as a plain body builds it.
//
// Why (docs/methodology.md, "The tax of adaptivity"): Bullet's step walks its node array (integration, one DBVT
// update per node) and its link array (the solver), and a plain body's arrays are row-major, so consecutive
// elements are neighbours on the cloth and share cache lines and DBVT ancestors. Operations append new nodes and
// links at the end and fill holes by swap-with-last; left alone, that scatters neighbours over the arrays, and the
// same Bullet instructions then miss the L1 cache about twice as often (callgrind, scripts/profile/step-profile.sh).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "softbody/bullet_setup.h"
#include "softbody/tc_softbody_impl.h"

namespace tcsb {

namespace {

/// Moves element order[i] to position i in both arrays `a` and `b` (kept parallel), following the permutation's
/// cycles: one copy per element and one temporary per cycle, no second array. Marks `order` as it goes (its entries
/// are negative afterwards).
template <class A, class B>
void permute_in_place(std::vector<std::int32_t>& order, A& a, B& b) {
  const auto n = static_cast<std::int32_t>(order.size());
  for (std::int32_t start = 0; start < n; ++start) {
    if (order[static_cast<std::size_t>(start)] < 0 || order[static_cast<std::size_t>(start)] == start) continue;
    auto a_stash = a[start];
    auto b_stash = b[static_cast<std::size_t>(start)];
    for (std::int32_t to = start;;) {
      const std::int32_t from = order[static_cast<std::size_t>(to)];
      order[static_cast<std::size_t>(to)] = -1 - from;
      if (from == start) {
        a[to] = a_stash;
        b[static_cast<std::size_t>(to)] = b_stash;
        break;
      }
      a[to] = a[from];
      b[static_cast<std::size_t>(to)] = b[static_cast<std::size_t>(from)];
      to = from;
    }
  }
}

/// position[order[i]] = i.
void invert(const std::vector<std::int32_t>& order, std::vector<std::int32_t>& position) {
  position.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    position[static_cast<std::size_t>(order[i])] = static_cast<std::int32_t>(i);
}

}  // namespace

void TcSoftBody::Impl::restore_order() {
  const LodTree& lod = tree();
  const int n = body_.m_nodes.size();
  // Nodes by their blocks' spatial ranks, which are distinct: each simulated node writes its index to its rank's slot
  // and sets the rank's bit, and a scan of the bits reads them out in order, no comparison. A word of bits at a time:
  // at a small budget the cut holds a node for every ten or so of the tree's, and a scan of every slot cost more than
  // the rest of the node order. O(N + tree size / 64); only the slots of set bits are read, so none is cleared.
  rank_slots_.resize(lod.size());
  rank_bits_.assign((lod.size() + 63) / 64, 0);
  for (std::int32_t i = 0; i < n; ++i) {
    const auto rank = static_cast<std::size_t>(lod.spatial_rank(tree_of_[static_cast<std::size_t>(i)]));
    rank_slots_[rank] = i;
    rank_bits_[rank / 64] |= std::uint64_t{1} << (rank % 64);
  }
  order_.resize(static_cast<std::size_t>(n));
  std::int32_t* next = order_.data();  // (written in place: a push_back per element costs a capacity check each)
  for (std::size_t w = 0; w < rank_bits_.size(); ++w)
    for (std::uint64_t bits = rank_bits_[w]; bits != 0; bits &= bits - 1)
      *next++ = rank_slots_[w * 64 + static_cast<std::size_t>(std::countr_zero(bits))];
  invert(order_, position_);

  // Links hold raw pointers into the node array: re-point them to where their nodes go, then move the nodes.
  Node* const base = &body_.m_nodes[0];
  for (int li = 0; li < body_.m_links.size(); ++li)
    for (Node*& end : body_.m_links[li].m_n) end = base + position_[static_cast<std::size_t>(end - base)];
  // So do Bullet's anchors (one that points at no simulated node stays as it is, for validate() to name).
  for (int a = 0; a < body_.m_anchors.size(); ++a) {
    const std::ptrdiff_t i = body_.m_anchors[a].m_node - base;
    if (i >= 0 && i < n) body_.m_anchors[a].m_node = base + position_[static_cast<std::size_t>(i)];
  }
  permute_in_place(order_, body_.m_nodes, tree_of_);
  faces_stale_ = true;           // faces hold Node* too: rebuilt before the next step
  interfaces_prepared_ = false;  // and so do the prepared interfaces
  for (int i = 0; i < n; ++i) {
    body_.m_nodes[i].m_leaf->data = &body_.m_nodes[i];
    set_bullet_index(tree_of_[static_cast<std::size_t>(i)], i);
  }

  // Links by (lower endpoint, higher endpoint), a plain net's order: each node in turn gives its links to later
  // nodes, nearest first, read from its incidence list (at most IncidenceList::kCapacity). O(L).
  order_.resize(static_cast<std::size_t>(body_.m_links.size()));
  next = order_.data();
  for (std::int32_t i = 0; i < n; ++i) {
    const TreeId id = tree_of_[static_cast<std::size_t>(i)];
    // The links to later nodes by their other endpoint, sorted by insertion. (Left uninitialised: zeroing them cost
    // as much as sorting them.)
    std::array<std::int32_t, IncidenceList::kCapacity> later_end, later_link;
    std::size_t count = 0;
    for (const std::int32_t li : incidence_[static_cast<std::size_t>(id)]) {
      // (from the flat mirror of the Bullet indices: a record read per entry would cost a cache line each)
      const std::int32_t other = bullet_[static_cast<std::size_t>(link_meta_[static_cast<std::size_t>(li)].other(id))];
      if (other < i) continue;
      std::size_t at = count++;
      for (; at > 0 && later_end[at - 1] > other; --at) {
        later_end[at] = later_end[at - 1];
        later_link[at] = later_link[at - 1];
      }
      later_end[at] = other;
      later_link[at] = li;
    }
    next = std::copy_n(later_link.begin(), count, next);
  }
  invert(order_, position_);
  permute_in_place(order_, body_.m_links, link_meta_);
  for (InterfaceConstraint& c : interfaces_)
    for (std::int32_t& handle : c.links) handle = position_[static_cast<std::size_t>(handle)];
  // Incidence lists name links by index: each entry follows its link.
  for (const TreeId id : tree_of_) incidence_[static_cast<std::size_t>(id)].renumber(position_);
  displaced_ = 0;
  ++order_restorations_;
  if (listener_ != nullptr) listener_->arrays_reordered();
}

void TcSoftBody::Impl::settle_order() {
  if (settings_.exact_order && displaced_ > 0) restore_order();
}

void TcSoftBody::Impl::rebuild_node_dbvt() {
  body_.m_ndbvt.clear();
  body_.m_ndbvt.m_leaves = 0;  // Bullet's clear() frees every node but leaves the count as it was
  dbvt_nodes_.release();
#ifdef __GLIBC__
  // The freed tree nodes sit in malloc's fast bins, one by one, spread over the old tree's allocation: taken again
  // from there, the new tree would be as scattered as the old. Trimming first merges them into large free blocks,
  // from which the new nodes are then carved one after the other.
  malloc_trim(0);
#endif
  insert_node_leaves(body_, order_);  // as a plain body's tree, boxed as Bullet's update would box the moving nodes
  dbvt_peak_nodes_ = body_.m_nodes.size();
  ++dbvt_rebuilds_;
}

}  // namespace tcsb
