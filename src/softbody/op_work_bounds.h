// Upper bounds on the work of one TreeCut operation (OpWork, op_sample.h), derived from the cut's invariants, so
// that "the operations are constant in time" (paper, Figure 4) becomes a deterministic statement: whatever the size
// of the net, no operation counts more than these. The op_work claims (paper/op_work_claims.h) and the scaling test
// (tests/paper/op_work_scaling_test.cpp) check measured maxima against them.
//
// The invariants the derivations use (tc_softbody.h, incidence_list.h, cut_adjacency.h):
//  (B) Balanced cut: cut nodes whose blocks share an edge are at most one level apart, so a side of a block has at
//      most two cut neighbours (two when they are one level finer) and a node at most 8 steady links.
//  (C) A block has at most 4 children (LodNode::child_count).
//  (D) No node has more than IncidenceList::kCapacity = 12 links at any time (the list throws beyond).
//  (W) The neighbour walk (for_each_cut_neighbour) probes at most 4 tree nodes per side: the node across, the one
//      above it, the two children of the one across; so at most 16 probes and 8 visits.
//  (A) Admission: an operation begins only when its block's cut neighbours are active (can_refine, can_coarsen), and
//      no operation begins next to a blending one, since every would-be operation's walk would meet an arriving
//      node. So between a begin and its end nothing around the block changes, and:
//        refine(p): p's neighbours are at p's level or one finer (a coarser one must be refined first), so each of
//          p's children has at most one cut neighbour per side (at its own level or at p's), and p has <= 8 links.
//        coarse(p): the walk from p admits nothing finer than p's children, so each child has at most one cut
//          neighbour per side and <= 4 links.
//
// Counts per primitive (tc_softbody.cpp), as OpWork defines them:
//   add_node:    nodes 2, tree_records 2, dbvt_leaves 1
//   remove_node: nodes 1, tree_records 1, dbvt_leaves 1;
//                relocation_nodes 1 and relocation_links <= 12 (the node moved into the hole, its links re-pointed,
//                (D))
//   add_link:    links 1, tree_records 2
//   remove_link: links 1, tree_records 2; relocation_links 1 (the last link moved into its place)
//   refresh of a link constant: links 1, tree_records 2
//   set_simulated_mass: nodes 1, tree_records 1
//   the neighbour walk: tree_records 1 + its probes
//
// The relocation counts are the swap-with-last's: which node or link is last in Bullet's arrays is a draw unrelated
// to the operation's block, so they are kept apart from the block-local counts (nodes, links, tree records, DBVT
// leaves), whose maxima and interior means then depend on the block's neighbourhood alone (paper/op_work_claims.h).
//
// Measured maxima (paper and ci suites, and tests/paper/op_work_scaling_test.cpp on 33^2 .. 1025^2) reach the bound
// for every count of end-refine, for nodes and DBVT leaves of every operation, coarse's links and end-coarse's
// relocated nodes; the rest stay below it: refine links 32 of 36 and tree records 90 of 114, coarse tree records 82
// of 84, end-coarse links 32 of 36, tree records 58 of 66 and relocated links 64 of 68 (those bounds sum worst cases
// that cannot all occur in one call).
#pragma once

#include <cstdint>

#include "../softbody/incidence_list.h"
#include "../softbody/op_sample.h"

namespace tcsb::op_work_bounds {

inline constexpr int kMaxChildren = 4;                       ///< (C)
inline constexpr int kMaxSteadyDegree = 8;                   ///< (B): two neighbours per side
inline constexpr int kMaxDegree = IncidenceList::kCapacity;  ///< (D): 12
inline constexpr int kMaxWalkProbes = 16;                    ///< (W)
inline constexpr int kMaxWalkVisits = kMaxSteadyDegree;      ///< (W), (B)
/// (A): one cut neighbour per side of a child of the block (refine's new children, coarse's old ones).
inline constexpr int kMaxChildDegree = 4;
/// (A), refine: a child's walk finds the node across at its own level (1 probe) or, failing that, p's neighbour one
/// level up (2 probes); it never needs the children of the node across.
inline constexpr int kMaxRefineChildProbes = 2 * 4;

// ---- refine(p): p active with <= 8 steady links; adds its <= 4 children -----------------------------------------
/// Links a refine adds: each child's walk visits <= kMaxChildDegree nodes (links among the children are added once,
/// so this overcounts), plus one tether per child.
inline constexpr int kRefineLinksAdded = kMaxChildren * (kMaxChildDegree + 1);  // 20
inline constexpr OpWork kRefine{
    .nodes = 1                                                    // p's position and velocity
             + kMaxSteadyDegree                                   // the affine fit reads each neighbour's position
             + kMaxChildren * 2                                   // add_node per child
             + 1,                                                 // p's mass halved
    .links = kMaxSteadyDegree                                     // the affine fit visits p's links
             + kMaxSteadyDegree                                   // p's links start fading: constants refreshed
             + kRefineLinksAdded,                                 // add_link
    .tree_records = 1                                             // p
                    + kMaxSteadyDegree                            // the fit's neighbours
                    + kMaxChildren * (1 + 2)                      // each child, and add_node's two records
                    + 1                                           // p's mass
                    + 2 * kMaxSteadyDegree                        // refreshing p's links
                    + kMaxChildren * (1 + kMaxRefineChildProbes)  // the children's walks
                    + 2 * kRefineLinksAdded,                      // add_link
    .dbvt_leaves = kMaxChildren,                                  // one leaf per child
    .relocation_nodes = 0,                                        // nothing removed
    .relocation_links = 0,
    .dbvt_ancestors = 0,  // not bounded by the cut (OpWork::dbvt_ancestors)
};

// ---- end-refine(p): removes p, its <= 8 faded links and <= 4 tethers -------------------------------------------
/// Links p holds at the end: its <= 8 links of the begin, all fading out ((A): nothing next door changed), and one
/// tether per child.
inline constexpr int kEndRefineLinksRemoved = kMaxSteadyDegree + kMaxChildren;  // 12
/// Links the children hold once the tethers are gone: <= kMaxChildDegree each, visited once per endpoint.
inline constexpr int kEndRefineChildLinkVisits = kMaxChildren * kMaxChildDegree;  // 16
inline constexpr OpWork kEndRefine{
    .nodes = 1                                        // p's velocity
             + kMaxChildren * 2                       // each child's velocity, and its full mass
             + 1,                                     // remove_node(p)
    .links = kEndRefineLinksRemoved                   // remove_link
             + kEndRefineChildLinkVisits              // faded-in links made steady
             + kEndRefineChildLinkVisits,             // the children's constants refreshed
    .tree_records = 1                                 // p
                    + 2 * kEndRefineLinksRemoved      // remove_link
                    + kMaxChildren * (1 + 1)          // each child, and its mass
                    + 1                               // remove_node(p)
                    + 2 * kEndRefineChildLinkVisits,  // refreshing the children's links
    .dbvt_leaves = 1,                                 // p's leaf removed
    .relocation_nodes = 1,                            // remove_node(p): the node moved into its place
    .relocation_links = kEndRefineLinksRemoved        // remove_link: the last link moved into each hole
                        + kMaxDegree,                 // remove_node(p) re-points the moved node's links
    .dbvt_ancestors = 0,                              // nothing inserted
};

// ---- coarse(p): p off, its <= 4 children active with <= 4 links each; adds p -------------------------------------
/// Links among and out of the children, seen from each child (each link among them is seen twice).
inline constexpr int kCoarseChildLinkVisits = kMaxChildren * kMaxChildDegree;  // 16
/// Links a coarse adds: one to each cut neighbour of p (the walk visits <= 8), one tether per child.
inline constexpr int kCoarseLinksAdded = kMaxWalkVisits + kMaxChildren;  // 12
inline constexpr OpWork kCoarse{
    .nodes = kMaxChildren                         // each child's position and velocity
             + 2                                  // add_node(p)
             + kMaxChildren,                      // each child's mass halved
    .links = kCoarseChildLinkVisits               // the children's links: role set, constant refreshed
             + kCoarseLinksAdded,                 // add_link
    .tree_records = 1                             // p
                    + kMaxChildren                // each child
                    + 2                           // add_node(p)
                    + kMaxChildren                // each child's mass
                    + 2 * kCoarseChildLinkVisits  // refreshing the children's links
                    + 1 + kMaxWalkProbes          // p's walk
                    + 2 * kCoarseLinksAdded,      // add_link
    .dbvt_leaves = 1,                             // p's leaf
    .relocation_nodes = 0,                        // nothing removed
    .relocation_links = 0,
    .dbvt_ancestors = 0,  // not bounded by the cut (OpWork::dbvt_ancestors)
};

// ---- end-coarse(p): removes the <= 4 children, their links and the tethers ---------------------------------------
/// Links the children hold at the end: each its <= 4 links of the begin (fading out or doomed) and its tether. Every
/// removed link is incident to a child, so this bounds the removals.
inline constexpr int kEndCoarseLinksRemoved = kMaxChildren * (kMaxChildDegree + 1);  // 20
inline constexpr OpWork kEndCoarse{
    .nodes = 1                                        // p's velocity
             + kMaxChildren                           // each child's velocity
             + 1                                      // p's full mass
             + kMaxChildren,                          // remove_node per child
    .links = kEndCoarseLinksRemoved                   // remove_link
             + kMaxWalkVisits                         // p's faded-in links made steady
             + kMaxWalkVisits,                        // p's constants refreshed
    .tree_records = 1                                 // p
                    + kMaxChildren                    // each child's incidence list
                    + 2 * kEndCoarseLinksRemoved      // remove_link
                    + 1                               // p's mass
                    + kMaxChildren                    // remove_node per child
                    + 2 * kMaxWalkVisits,             // refreshing p's links
    .dbvt_leaves = kMaxChildren,                      // each child's leaf removed
    .relocation_nodes = kMaxChildren,                 // remove_node per child: a node moved into each hole
    .relocation_links = kEndCoarseLinksRemoved        // remove_link: the last link moved into each hole
                        + kMaxChildren * kMaxDegree,  // remove_node re-points each moved node's links
    .dbvt_ancestors = 0,                              // nothing inserted
};

/// The bound of one operation.
constexpr const OpWork& bound(OpKind kind) {
  switch (kind) {
    case OpKind::kRefine: return kRefine;
    case OpKind::kEndRefine: return kEndRefine;
    case OpKind::kCoarse: return kCoarse;
    case OpKind::kEndCoarse: return kEndCoarse;
  }
  return kRefine;
}

}  // namespace tcsb::op_work_bounds
