// OpSample: the cost of one TreeCut operation, split as the paper's Table 1 splits it.
#pragma once

#include <cstdint>

#include "../softbody/op_kind.h"

namespace tcsb {

/// The work one operation did, counted where it is done (tc_operations.cpp, tc_softbody.cpp), so that the counts
/// are deterministic and a loop over anything sized by the net would show in them. Each counting site adds one per
/// item it handles; an item handled at two sites (a link made steady, then its constant refreshed) counts twice.
/// Prefetches (tc_prefetch.cpp) and the sink call are not counted: they change nothing. The derived upper bounds
/// per operation are in softbody/op_work_bounds.h.
struct OpWork {
  /// Bullet nodes (btSoftBody::Node) of the operation's block appended, removed, or read or written: the parent's
  /// position and velocity a refine places children from, each neighbour's position the affine fit reads, each
  /// child a coarse averages, each node whose mass or velocity is set, the node whose DBVT leaf a new leaf is put
  /// beside. A node a swap-with-last moves counts in relocation_nodes instead.
  std::int32_t nodes = 0;
  /// Bullet links (with their CutLink) of the block created or removed, whose constant is written, or visited in an
  /// incidence list (the affine fit's neighbours, links made steady). Links a swap-with-last moves or re-points
  /// count in relocation_links instead.
  std::int32_t links = 0;
  /// Per-tree-node entries (LodNode, cut state, NodeRecord, incidence list) read or written: the operation's block,
  /// every cut-membership probe of the neighbour walk, both endpoints of every link created, removed or refreshed.
  std::int32_t tree_records = 0;
  /// DBVT leaves inserted (one per node added) or removed (one per node removed).
  std::int32_t dbvt_leaves = 0;
  /// Nodes a removal's swap-with-last moves into the hole: whichever node is last in Bullet's array, a draw unrelated
  /// to the block. Each is copied, its DBVT leaf re-pointed, its Bullet index and tree entry rewritten (O(1) each).
  std::int32_t relocation_nodes = 0;
  /// Links a swap-with-last moves or re-points: the last link moved into a removed link's place (both endpoints'
  /// incidence entries rewritten), and each link of a moved node re-pointed to its new address.
  std::int32_t relocation_links = 0;
  /// Internal DBVT boxes an insertion beside a leaf enlarged or found already containing the new pair: the walk
  /// up from the new pair that stops at the first ancestor containing it (dbvt_local.h). Not bounded by the cut's
  /// invariants: it depends on where the new node lies relative to its neighbours' boxes.
  std::int32_t dbvt_ancestors = 0;
  /// Whether the operation's block lies away from the net's border: its 3x3 neighbourhood of blocks of its level
  /// is inside the net (neighbourhood_inside_net, net/cut_adjacency.h). Interior calls all see the same geometry
  /// on every net; border calls see fewer neighbours, and their share falls as 1 / width.
  bool interior = false;
};

/// The counts of OpWork, to loop over them.
enum class OpWorkCount : std::uint8_t {
  kNodes,
  kLinks,
  kTreeRecords,
  kDbvtLeaves,
  kRelocationNodes,
  kRelocationLinks,
  kDbvtAncestors
};
inline constexpr int kOpWorkCountKinds = 7;

/// Name used in reports: the OpWork member's name ("nodes", "links", "tree_records", "dbvt_leaves",
/// "relocation_nodes", "relocation_links", "dbvt_ancestors").
inline const char* op_work_count_name(OpWorkCount count) {
  switch (count) {
    case OpWorkCount::kNodes: return "nodes";
    case OpWorkCount::kLinks: return "links";
    case OpWorkCount::kTreeRecords: return "tree_records";
    case OpWorkCount::kDbvtLeaves: return "dbvt_leaves";
    case OpWorkCount::kRelocationNodes: return "relocation_nodes";
    case OpWorkCount::kRelocationLinks: return "relocation_links";
    case OpWorkCount::kDbvtAncestors: return "dbvt_ancestors";
  }
  return "?";
}

/// One count of `work`.
constexpr std::int32_t op_work_count(const OpWork& work, OpWorkCount count) {
  switch (count) {
    case OpWorkCount::kNodes: return work.nodes;
    case OpWorkCount::kLinks: return work.links;
    case OpWorkCount::kTreeRecords: return work.tree_records;
    case OpWorkCount::kDbvtLeaves: return work.dbvt_leaves;
    case OpWorkCount::kRelocationNodes: return work.relocation_nodes;
    case OpWorkCount::kRelocationLinks: return work.relocation_links;
    case OpWorkCount::kDbvtAncestors: return work.dbvt_ancestors;
  }
  return 0;
}

/// One operation: time spent on nodes (adding/removing Bullet nodes, DBVT leaves, placement, mass and velocity)
/// and on links (creating, deleting, re-pointing, incidence lists, constants), and the body's size at the time.
struct OpSample {
  OpSample() = default;
  /// (A constructor rather than aggregate initialisation, so callers that predate `work` may leave it out.)
  OpSample(OpKind kind, std::int32_t node_ns, std::int32_t link_ns, std::int32_t nodes, std::int32_t links,
           const OpWork& work = {})
      : kind(kind), node_ns(node_ns), link_ns(link_ns), nodes(nodes), links(links), work(work) {}
  OpKind kind = OpKind::kRefine;
  std::int32_t node_ns = 0;
  std::int32_t link_ns = 0;
  std::int32_t nodes = 0;  ///< Bullet nodes present when the operation ran
  std::int32_t links = 0;  ///< Bullet links present when the operation ran
  OpWork work;             ///< what the operation touched (deterministic)
};

/// Where a body reports its operations; the runner records them, tests may ignore them.
class OpSink {
 public:
  virtual ~OpSink() = default;
  virtual void record(const OpSample& sample) = 0;
};

/// A sink that only counts the operations begun or ended, so a caller knows when a body's surface may have jumped.
class OpCounter final : public OpSink {
 public:
  void record(const OpSample&) override { ++count; }
  std::int64_t count = 0;
};

}  // namespace tcsb
