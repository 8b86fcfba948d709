// TcSettings: how a TreeCut soft body performs its operations.
#pragma once

#include <vector>

namespace tcsb {

/// Where refine places the children of a node.
enum class Placement {
  kAffine,  ///< parent position + local deformation (least-squares affine fit over the neighbourhood) x rest offset
  kRigid,   ///< parent position + rest offset (the paper's placement)
};

/// How the cloth is joined where a coarse block meets finer cloth (docs/design.md, "Interfaces between levels").
enum class Interfaces {
  kLinks,  ///< the paper's: the coarse node is linked to each finer node facing it, a fan of two links per side
  /// one constraint per fan: the coarse node to the midpoint of the two finer nodes (hanging-node style); on a tree
  /// resting on first leaves, the vertex kinds of InterfaceKind
  kHanging,
};

/// What mass a simulated node carries (docs/design.md, "Masses that follow the cut").
enum class Masses {
  kBlocks,  ///< its block's leaves' sum (the paper's)
  /// Each leaf's mass shared among the cut's nodes by the bilinear weights between a block's node and the nodes at
  /// its far corners, as a lumped finite-element mass matrix shares it; needs blocks resting on their first leaf
  /// (RestPlacement::kVertex). Operations move mass between a block and its neighbours, momentum kept.
  kCut,
};

/// Settings of the TreeCut soft body's operations.
struct TcSettings {
  int blend_steps = 5;  ///< K: steps over which leaving links fade out and arriving links fade in
  /// The cut a body starts at: 0, the finest (every grid node, identical to a plain body), or the LOD level whose
  /// blocks the whole cloth starts as, where they may be simulated (TcSoftBody::coarsen_to_level). A body under a
  /// budget otherwise spends its first steps coarsening: 55 steps to reach 30 % on a 65^2 net, 150 on 129^2.
  int start_level = 0;
  Placement placement = Placement::kAffine;
  /// kLinks keeps Bullet's own solve, bit for bit the paper's method; kHanging solves the body's constraints in
  /// TcSoftBody::solve_constraints (Bullet's solvers in Bullet's sequence, then the interface constraints, every
  /// position iteration).
  Interfaces interfaces = Interfaces::kLinks;
  /// kBlocks keeps the paper's masses bit for bit; kCut requires the net's tree built with RestPlacement::kVertex.
  Masses masses = Masses::kBlocks;
  /// Resolution-consistent material: the link stiffness kLST per LOD level, from level 1 on (entry i is level i + 1;
  /// levels past the end use the last entry). A link belongs to the level of its coarser endpoint; level-0 links
  /// (and every link, when this is empty: uncalibrated) use the solver's material. Values from a calibration
  /// (fidelity/calibration.h), each in (0, 1]. Applied through Bullet's per-link materials: no per-step cost.
  std::vector<double> level_stiffness;
  /// Keep Bullet's node and link arrays in a plain body's spatial order (TcSoftBody::restore_order) while
  /// operations change the cut. Off: the arrays stay in the order the operations leave them (for measuring what the
  /// order costs; docs/methodology.md, "The tax of adaptivity").
  bool restore_order = true;
  /// ... but only while the body simulates at least this many nodes. Below, its arrays fit a core's L2 (8 192
  /// Bullet nodes are about 2 MiB), where order saves little and the pass measured a net cost on the paper's nets;
  /// from 257^2 on it saved 29-45 % of a step (docs/methodology.md, "Bullet's arrays in a plain body's order"). A
  /// node count, not a cache size read from the machine, so that a body's behaviour is the same on every machine.
  int restore_order_min_nodes = 8192;
  /// restore_order runs once operations have displaced this fraction of the nodes and links simulated: the arrays
  /// stay at least 3/4 in order, and the O(N + L + tree) pass runs once per (N + L)/4 displacements: amortised O(1)
  /// each at a fixed compression (about 4 x 50 instructions). 1/8 missed the L1 no less often in Bullet's step and cost
  /// twice the passes; 1/2 fewer passes, but half the arrays out of order (callgrind, scripts/profile/step-profile.sh;
  /// docs/methodology.md).
  static constexpr double kReorderFraction = 1.0 / 4;
  /// Restore the order whenever operations moved an element, on a body of any size (whatever restore_order and
  /// restore_order_min_nodes say; TcSoftBody::settle_order, after advance_blends() and after a controller's
  /// operations): Bullet then sweeps the links in a plain body's order at every step. Off by default, as the paper's
  /// body is. Where the solver does
  /// not converge the order is part of the cloth's material: Bullet's position solve is a Gauss-Seidel sweep, and a
  /// sweep in grid order carries a correction along a row within one iteration where a scattered order does not; a
  /// cut mostly at level 0 with a coarse disk in it errs 1.17 % RMS on an 81^2 net at 32 iterations with its arrays
  /// as the operations left them and 0.08 % with them in order (docs/investigations/link-order-material.md).
  bool exact_order = false;
  /// With restore_order, on bodies of at least restore_order_min_nodes: once the body has shrunk to
  /// 1/kDbvtRebuildShrink of its largest node count since the node DBVT was last built, rebuild that tree as a plain
  /// body builds it (TcSoftBody::rebuild_node_dbvt). A body coarsened from the full net otherwise keeps its tree nodes
  /// scattered over the full tree's allocation, and the per-step leaf updates miss the cache where a plain body of its
  /// size does not (docs/methodology.md, "The node DBVT as a plain body has it").
  bool rebuild_dbvt = true;
  /// Whether the nodes an operation adds (a refine's children, a coarse's parent) take part in soft-rigid contact
  /// while it blends. True (the default): from the moment they appear, so no arriving node passes through a
  /// collider unheld. False: the paper's rule (sections 3.3-3.4: new nodes "are excluded from collision
  /// calculations, for now" and their "collision shapes are inserted" when the operation ends), through Bullet's
  /// per-node m_battach, which btSoftColliders::CollideSDF_RS::DoNode skips; the nodes keep their DBVT leaves.
  /// Leaving nodes collide until they go either way.
  bool arrivals_collide = true;
  static constexpr double kDbvtRebuildShrink = 1.3;
};

}  // namespace tcsb
