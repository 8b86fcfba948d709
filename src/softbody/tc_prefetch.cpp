// TcSoftBody::Impl::prefetch_footprint(): starts loading the cache lines an operation is about to touch.
//
// Why: an operation executes a few thousand instructions whatever the size of the net, but it reads a few dozen
// cache lines scattered over arrays sized by the net (the tree, the per-tree-node arrays, Bullet's nodes and links).
// Once those arrays outgrow the L2 cache (between 65^2 and 129^2 grid nodes) each of those reads misses, and in
// program order the misses queue one behind the other: the operation's wall time grows with N although its work
// does not (docs/methodology.md, "Operations in constant time"). Prefetching the footprint in waves — each wave's
// addresses come from the lines the previous wave loaded — lets the misses of a wave overlap: the operation then
// waits for about one memory latency per wave instead of one per line.
//
// Measured (tcsb_bench, begin operations, builds with and without it run alternately, 3 rounds): at 513^2 refine
// 5.0-7.0 -> 3.6-3.9 us and coarse 4.0-6.0 -> 3.4-3.6 us; at 33^2-65^2 inside the noise. The end operations do
// not call it: their blocks were touched by the blend steps just before, and there it only cost time (in real runs
// too: with it, end-refine's and end-coarse's cost grew no less from n45 to n81 — docs/methodology.md, "Tried and
// left out").
//
// What the end operations miss instead (callgrind on a real run, n81 at 75 %) is mostly outside their block: each
// link they remove is swapped with the array's last link, whose two endpoints' incidence lists are re-pointed, and
// the removed link's other endpoint loses it from its list — 18 of end-refine's 45 lines from beyond a 2 MiB cache,
// 32 of end-coarse's 85. prefetch_link_removals() asks for those lines all at once before the removals start.
// Measured in real runs (paper suite without fidelity, 5 runs with and 5 without, alternating): end-refine 2.05 ->
// 1.69 us at n45 and 2.49 -> 2.02 us at n81, end-coarse 3.50 -> 2.89 and 3.96 -> 3.29 us (medians of the runs'
// per-net medians), while the begin operations, unchanged, moved by 0-6 %. In tcsb_bench, whose end operations
// follow their begin at once (everything hot), it costs about 60-130 ns per call.
//
// Prefetching overlaps misses but cannot make them free: a core keeps only 10-16 in flight, so an operation's time
// on a large net follows the number of distinct lines it touches. That is why the per-tree-node data an operation
// needs sits in one 32-byte record (Impl::NodeRecord), the LOD node fits one line, link constants are computed
// from the records (no neighbour's Bullet node is touched, and of a link only its constant's line), and the
// removals here ask for the removed links' lines, which the begin operation no longer loads. Lines from beyond a
// 2 MiB simulated cache per call at 513^2 (scripts/profile/op-instructions.sh), before -> after those changes:
// begin-refine 64.8 -> 46.8, begin-coarse 81.2 -> 60.0, end-refine 3.2 -> 7.9, end-coarse 17.2 -> 26.8 (the bench's end
// operation follows its begin at once, so lines a begin no longer touches show up there). In real runs every
// operation got cheaper and flatter (docs/methodology.md, "Operations in constant time").
//
// GCC treats __builtin_prefetch as free of effects and may delete a loop that only prefetches, without a warning.
// The CTest test softbody.prefetch_instructions_emitted counts the instructions left in this file's object
// (scripts/check-prefetch-emitted.sh); when adding prefetch calls here, raise its minimum to match.
#include "softbody/tc_softbody_impl.h"

namespace tcsb {

namespace {

template <class T>
inline void prefetch(const T* p) {
  __builtin_prefetch(static_cast<const void*>(p), 1, 3);
}

/// Both ends of an object that may straddle two cache lines.
template <class T>
inline void prefetch_object(const T* p) {
  prefetch(p);
  prefetch(reinterpret_cast<const char*>(p) + sizeof(T) - 1);
}

/// The lines of a Bullet node an operation reads: position, velocity, and inverse mass with the DBVT leaf (bytes 16,
/// 48 and 112-128 of the 256-byte Node). Three lines, not two: Bullet's node array starts 32 bytes into a line
/// (btAlignedAlloc aligns to 16), so position and velocity fall on different lines.
inline void prefetch_node(const btSoftBody::Node& n) {
  prefetch(&n.m_x);
  prefetch(&n.m_v);
  prefetch(&n.m_leaf);
}

}  // namespace

void TcSoftBody::Impl::prefetch_footprint(TreeId id) const {
  if constexpr (!TCSB_OP_PREFETCH) return;
  const LodNode& node = tree().node(id);  // waits for one line: the block's children come from it
  TreeId block[5] = {id, kNoTreeNode, kNoTreeNode, kNoTreeNode, kNoTreeNode};
  int count = 1;
  for (int i = 0; i < node.child_count; ++i) block[count++] = node.children[static_cast<std::size_t>(i)];

  // Wave 1: the tree side of the block (the node and its children). LOD node, incidence list and record are one
  // cache line each.
  for (int i = 0; i < count; ++i) {
    const auto x = static_cast<std::size_t>(block[i]);
    prefetch(&tree().node(block[i]));
    prefetch(&incidence_[x]);
    prefetch(&record_[x]);
    prefetch(&bullet_[x]);
    prefetch(&state_[x]);
  }
  // Wave 2: the block's simulated Bullet nodes, and their links (Bullet's and ours).
  for (int i = 0; i < count; ++i) {
    const NodeRecord& r = record(block[i]);
    if (r.bullet >= 0) prefetch_node(body_.m_nodes[r.bullet]);
    for (std::int32_t li : incidence_[static_cast<std::size_t>(block[i])]) {
      prefetch(&link_meta_[static_cast<std::size_t>(li)]);
      prefetch(&body_.m_links[li].m_c0);  // a begin operation rewrites only the link's constant
    }
  }
  // Wave 3: the block's DBVT leaves (a begin operation inserts the new leaves beside them), and the neighbours at
  // the other end of the links: their tree-side records.
  for (int i = 0; i < count; ++i) {
    const NodeRecord& r = record(block[i]);
    if (r.bullet >= 0) prefetch(body_.m_nodes[r.bullet].m_leaf);
  }
  for (int i = 0; i < count; ++i)
    for (std::int32_t li : incidence_[static_cast<std::size_t>(block[i])]) {
      const CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
      const auto n = static_cast<std::size_t>(meta.other(block[i]));
      prefetch(&incidence_[n]);
      prefetch(&record_[n]);
    }
  // Wave 4: the leaves' parents; and when a refine will fit the local deformation, the neighbours' positions (the
  // link constants take the neighbours' inverse masses from their records, so nothing else of their Bullet nodes).
  for (int i = 0; i < count; ++i) {
    const NodeRecord& r = record(block[i]);
    if (r.bullet >= 0) prefetch(body_.m_nodes[r.bullet].m_leaf->parent);
  }
  if (record(id).bullet < 0 || settings_.placement == Placement::kRigid) return;
  for (std::int32_t li : incidence_[static_cast<std::size_t>(id)]) {
    const CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
    const int n = record(meta.other(id)).bullet;
    if (n >= 0) prefetch(&body_.m_nodes[n].m_x);
  }
}

void TcSoftBody::Impl::prefetch_link_removals(std::span<const TreeId> ids) const {
  if constexpr (!TCSB_OP_PREFETCH) return;
  int removed = 0;
  for (const TreeId id : ids) {
    for (std::int32_t li : incidence_[static_cast<std::size_t>(id)]) {
      const CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
      prefetch(&incidence_[static_cast<std::size_t>(meta.other(id))]);
      // The removal overwrites the whole link; the begin operation and the blend touched only its constant's line.
      prefetch_object(&body_.m_links[li]);
      ++removed;
    }
  }
  // Each removal moves the array's last link into the hole and re-points it in its two endpoints' incidence lists.
  // The tail of the array is recent (hot); its endpoints are anywhere in the net.
  const int links = body_.m_links.size();
  for (int k = 1; k <= removed && k <= links; ++k) {
    const CutLink& moved = link_meta_[static_cast<std::size_t>(links - k)];
    prefetch(&incidence_[static_cast<std::size_t>(moved.a)]);
    prefetch(&incidence_[static_cast<std::size_t>(moved.b)]);
  }
}

}  // namespace tcsb
