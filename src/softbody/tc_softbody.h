// TcSoftBody: the TreeCut soft body — a btSoftBody whose simulated nodes are a cut through the net's LOD tree,
// refined and coarsened at run time in constant time, with link blending between the old and the new state.
//
// This header is the body's API: what an application calls. Everything else of the body (the cut's arrays, the
// incidence lists, the operations and their blending, the interface constraints, the faces, the order passes) is
// TcSoftBody::Impl, in the library's private header tc_softbody_impl.h, which says how the body stays inside
// Bullet's rules.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "../net/net.h"
#include "../softbody/solver_settings.h"
#include "../softbody/tc_settings.h"

namespace tcsb {

class CutListener;

/// Where a tree node stands with respect to the cut.
enum class CutState : std::uint8_t {
  kOff,       ///< not simulated
  kActive,    ///< simulated, in the cut, not part of an operation
  kArriving,  ///< simulated, joining the cut (its operation is blending)
  kLeaving,   ///< simulated, leaving the cut (its operation is blending)
};

/// What a link is doing.
enum class LinkRole : std::uint8_t {
  kSteady,   ///< an ordinary link of the cut
  kFadeIn,   ///< arriving: strength ramps up over the blend
  kFadeOut,  ///< leaving: strength ramps down, removed at the end
  kDoomed,   ///< full strength, removed at the end (links among the children a coarse replaces)
  kTether,   ///< full strength, between the old and the new nodes of an operation, removed at the end
};

/// A Bullet link seen from the tree: its endpoints and what it is doing. Kept parallel to btSoftBody::m_links.
struct CutLink {
  TreeId a = kNoTreeNode, b = kNoTreeNode;  ///< endpoints, as Bullet's m_n[0], m_n[1]
  LinkRole role = LinkRole::kSteady;
  std::int32_t op = -1;  ///< owning operation while not steady
  /// With hanging interfaces, the interface constraint this link is one of the two handles of (its m_c0 is then 0,
  /// so Bullet's link solver skips it), else -1.
  std::int32_t interface = -1;
  /// Links that join two nodes of the committed cut as neighbours (not the old cut's, not tethers).
  bool joins_committed() const { return role == LinkRole::kSteady || role == LinkRole::kFadeIn; }
  /// The endpoint that is not `end` (one of the two).
  TreeId other(TreeId end) const { return a == end ? b : a; }
};

/// Who settles the arrays' order (TcSoftBody::settle_order) after advance_blends() with TcSettings::exact_order.
/// kNow: advance_blends() itself, so the next step is in order whatever the caller does (the default). kByCaller: the
/// caller, with settle_order() once it has begun the boundary's operations too — at a boundary where operations end
/// and others begin, one restore (O(N + L + T)) instead of two. The order that results is the same: restore_order()
/// puts any set of nodes and links in one order, whatever order they were in.
enum class OrderSettling : std::uint8_t { kNow, kByCaller };

/// Why an operation may not begin now.
struct OpCheck {
  bool ok = false;
  /// When the cut would become unbalanced: a coarser neighbour that must be refined first (else kNoTreeNode).
  TreeId refine_first = kNoTreeNode;
  bool ok_or_blocked_by_neighbour() const { return ok || refine_first != kNoTreeNode; }
};

/// The result of validate(): every broken invariant, one line each.
struct Validation {
  bool ok() const { return problems.empty(); }
  std::vector<std::string> problems;
  std::string summary() const;
};

class TcSoftBody : public btSoftBody {
 public:
  /// Told from a TcSoftBody's destructor that it goes, while it is still whole (TreeCutDriver: forgets the body and
  /// takes it out of its world). One per body.
  class LifetimeListener {
   public:
    virtual ~LifetimeListener() = default;
    virtual void body_destroyed(TcSoftBody& body) = 0;
  };

  /// Builds the body at the finest cut (every grid node simulated), identical to the plain baseline, then, when
  /// settings.start_level > 0, coarsens it to that level (coarsen_to_level). `world` is the
  /// info of the world the body will live in — btSoftRigidDynamicsWorld::getWorldInfo() for a body in a collision
  /// world, or an info of its own for a body stepped solo —, and must outlive the body. A body made for a collision
  /// world (an info with a broadphase) collides with its rigid bodies from the start (m_cfg.collisions = SDF_RS,
  /// Bullet's own default); a body made for solo stepping has collisions off (Bullet would find nothing to collide
  /// with). Set m_cfg.collisions = 0 after construction for a cloth that should pass through the world's colliders.
  TcSoftBody(btSoftBodyWorldInfo& world, std::shared_ptr<const Net> net, const SolverSettings& solver,
             const TcSettings& settings);
  /// Tells the lifetime listener, if any (a TreeCutDriver), that the body goes.
  ~TcSoftBody() override;
  TcSoftBody(const TcSoftBody&) = delete;
  TcSoftBody& operator=(const TcSoftBody&) = delete;
  void set_lifetime_listener(LifetimeListener* listener);
  LifetimeListener* lifetime_listener() const;

  // ---- queries -----------------------------------------------------------------------------------------------
  const Net& net() const;
  const LodTree& tree() const;
  const TcSettings& settings() const;
  /// The solver settings and material the body was built with (material.h).
  const SolverSettings& solver() const;
  CutState state(TreeId id) const;
  /// In the committed (target) cut: active or arriving.
  bool committed(TreeId id) const;
  /// Bullet node index of a tree node, or -1 when it is not simulated.
  int bullet_index(TreeId id) const;
  /// Tree node simulated by Bullet node `index`.
  TreeId tree_id(int index) const;
  /// Per tree node states, Bullet indices, and per Bullet node tree ids: the cut as flat arrays. They change only
  /// inside operations and advance_blends(), never while Bullet steps, so a worker may read them during a step.
  std::span<const CutState> states() const;
  std::span<const std::int32_t> bullet_indices() const;
  std::span<const TreeId> tree_ids() const;
  /// Per Bullet link: endpoints and role (same stability as the arrays above).
  std::span<const CutLink> cut_links() const;
  /// Mass the node carries now (half of its block's while an operation blends it), kg. Pinned nodes included.
  double simulated_mass(TreeId id) const;
  int node_count() const { return m_nodes.size(); }
  int link_count() const { return m_links.size(); }
  /// Nodes of the committed cut (what the simulation converges to once blends end).
  int committed_count() const;
  /// Operations currently blending: the paper's I.
  int interpolations() const;

  // ---- operations --------------------------------------------------------------------------------------------
  /// Whether refine(id) may begin: id active, not a leaf and not anchored, its neighbours active and none coarser.
  OpCheck can_refine(TreeId id) const;
  /// Whether coarse(parent) may begin: all its children active and none anchored, it may be simulated (at most one
  /// pinned leaf), and its neighbours active and none finer than its children.
  OpCheck can_coarsen(TreeId parent) const;
  /// Whether a btSoftBody anchor (appendAnchor: a node attached to a rigid body) holds the simulated node `id`.
  /// Anchored nodes stay in the cut (no operation begins on their blocks), and every anchor follows its node through
  /// the body's reorderings (swap-with-last removals, restore_order); a node anchored while an operation removes it
  /// hands its anchor to the node that takes its place (the nearest child at a refine's end, the parent at a
  /// coarse's end). O(anchors).
  bool anchored(TreeId id) const;
  /// Begins replacing `id` by its children. Requires can_refine(id).ok. O(1).
  void begin_refine(TreeId id);
  /// Begins replacing the children of `parent` by `parent`. Requires can_coarsen(parent).ok. O(1).
  void begin_coarse(TreeId parent);
  /// Coarsens the body at once, before its first step, until every block that may be simulated is at `level`
  /// (levels past the tree's coarsest are the coarsest): level by level, rounds of begin_coarse on every node
  /// can_coarsen allows, each round's blends run to their end with no simulated time passing, so only the link
  /// constants move. What a body that starts coarse (TcSettings::start_level) and calibration's whole-level cuts
  /// use. Returns the committed node count. O(T) per level, T the tree's size.
  int coarsen_to_level(int level);
  /// Advances every blending operation by one step; ends those whose K steps are done. Call once per step boundary,
  /// before beginning new operations. O(interpolations); when TcSettings::restore_order is on and operations have
  /// displaced more than TcSettings::kReorderFraction of the arrays' elements, it then restores their order
  /// (restore_order(): O(N + L + T) once per (N + L)/4 displacements, T the tree's size, so amortised O(1 + T/N) per
  /// displacement: O(1) at any fixed compression, 4.4 N at 30 %); with TcSettings::exact_order, whenever anything
  /// was displaced (settle_order(): O(N + L + T) per such boundary). On bodies that shrank by
  /// TcSettings::kDbvtRebuildShrink since their node DBVT was built it rebuilds that tree too (rebuild_node_dbvt()).
  /// `settling` says who puts the arrays in order with TcSettings::exact_order (OrderSettling).
  void advance_blends(OrderSettling settling = OrderSettling::kNow);
  /// One solo step (predictMotion, solve_constraints(), integrateMotion), as a plain body outside any collision
  /// world steps. A body in a btSoftRigidDynamicsWorld is stepped by the world's stepSimulation instead, through
  /// TcSoftBodySolver (tc_softbody_solver.h), which calls solve_constraints() too.
  void simulate_step(btScalar dt);
  /// The body's constraint solve. With the paper's fans, or while the cut has no interface, Bullet's own
  /// btSoftBody::solveConstraints(). With hanging interfaces TC-SB's loop (tc_interfaces.cpp): Bullet's steps in
  /// Bullet's order — links prepared, anchors prepared, velocity iterations, position iterations each running the
  /// configured position solvers and then projecting every interface constraint, velocities from positions, drift —
  /// so a body without interfaces steps exactly as Bullet steps it.
  void solve_constraints();
  // ---- moving pins (softbody/pin_motion.h) -------------------------------------------------------------------
  /// Moves the pins along a scripted path (a rod holding the cloth, moved): over the next step every simulated
  /// pinned node goes to its rest position + `offset` (its velocity is set so that predictMotion carries it there,
  /// the same rule as StockPins for a stock body), and from then on operations place pinned nodes there and
  /// validate() expects them there. Call once per step boundary, after the boundary's operations, right before the
  /// step (SceneWorld::step does). O(N): a scan for the nodes of zero inverse mass, which only pinned nodes have.
  void move_pins(const btVector3& offset, btScalar dt);
  /// Where the pins are now, relative to their rest positions (zero until move_pins()), metres.
  const btVector3& pin_offset() const;
  /// Where a pinned tree node is now: its rest position + pin_offset().
  btVector3 pin_position(TreeId id) const;
  // ---- faces (tc_faces.cpp) ----------------------------------------------------------------------------------
  /// Gives the body Bullet faces over its committed cut from now on: what Bullet's aerodynamic model reads (node
  /// areas and normals), so a windy scene pushes TC-SB as it pushes a plain body (SceneWorld::attach calls it).
  /// Every corner where three or four blocks of the cut meet becomes a triangle or a quad of two — on the finest cut
  /// exactly a plain body's faces (bullet_setup.h, append_cell_faces), in the same order —, each with its area at
  /// rest, and each node's area Bullet's mean of its faces' (updateArea); leaving nodes have none. Off by default:
  /// the paper's cloth has no faces, and faces cost Bullet per-step work.
  void enable_faces();
  bool faces_enabled() const;
  /// Rebuilds the faces if the cut or the node array changed since they were built, then Bullet's node normals. Every
  /// step path calls it before predictMotion (simulate_step, step_body, TcSoftBodySolver); a no-op without faces.
  /// O(N + leaves) per rebuild (each committed block marks its leaves, then each node's corners are read);
  /// Bullet's own normal update is O(N + F) every step.
  void refresh_faces();

  /// Told of every change to the cut right after it is made, and of every reordering of Bullet's arrays (may be
  /// null; cut_listener.h).
  void set_cut_listener(CutListener* listener);

  // ---- array order (tc_order.cpp) ----------------------------------------------------------------------------
  /// Puts Bullet's node array back into the row-major order of the nodes' blocks on the net, and its link array
  /// into the order of their endpoints (lower index first, then higher), the order a plain body of the same nodes
  /// has from the start; the node DBVT's leaves follow their nodes. Operations append at the end and fill holes by
  /// swap-with-last, which would otherwise scatter neighbours over the arrays and cost the solver cache misses a
  /// plain body does not pay. Positions, velocities and every invariant are unchanged; the links' order is Bullet's
  /// solving order, so the simulation goes on differently (deterministically). On the finest cut it changes nothing.
  /// O(N + L + T), T the tree's size (a scan of one slot per tree node), no allocation after the first call. Must
  /// not run while a worker reads the cut (CutView).
  void restore_order();
  /// With TcSettings::exact_order, restore_order() if anything was displaced since the arrays were last in order;
  /// else nothing. advance_blends() calls it (unless told OrderSettling::kByCaller), and a controller calls it again
  /// once it has begun its boundary's operations, before it hands the cut to a worker, so Bullet's next step sweeps
  /// every link in a plain body's order.
  void settle_order();

  // ---- invariants --------------------------------------------------------------------------------------------
  /// Checks every invariant, one check each (docs/design.md, "Invariants: validate()"): the world around the body;
  /// its anchors; Bullet's nodes and the cut mapped both ways, one DBVT leaf per node, no NaN; masses lumped as the
  /// cut says, pinned nodes at rest (displaced by pin_offset()), total mass constant; links consistent with the cut
  /// (pointers, rest lengths, materials, constants as their roles say); the interface constraints; the faces;
  /// incidence lists equal to Bullet's link set; the committed and the old cut each a cut of every leaf; the
  /// committed cut balanced and linked to its neighbours; the operations in flight. O(N log N + L); for tests and
  /// debug runs.
  Validation validate() const;

  /// The least-squares affine map (3x2) from rest offsets in the net's plane (x, z) to current offsets, fitted over
  /// the node's linked neighbours, whatever the placement setting; the identity-in-plane when the neighbours do not
  /// span the plane. Reconstructing every grid node from the cut uses it for every body, so the measuring instrument
  /// is the same whether children are placed rigidly or not. O(degree).
  Eigen::Matrix<double, 3, 2> local_affine_fit(TreeId id) const;

  /// Linear momentum of the simulated nodes (pinned nodes excluded), kg m/s.
  Eigen::Vector3d linear_momentum() const;
  /// Total simulated mass (pinned nodes included through their bookkeeping mass), kg.
  double total_mass() const;

  /// The state behind the API (tc_softbody_impl.h, a private header of the library and the harness: tests and the
  /// benchmark reach the body's internals through it; a program using the installed package cannot).
  class Impl;
  Impl& impl() { return *impl_; }
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tcsb
