// TcSoftBody::Impl: everything of the TreeCut soft body behind its public API (tc_softbody.h) — the cut's flat
// arrays, the incidence lists, the operations, the interface constraints, the faces, the order passes and the checks
// of validate(). Private to the library and the harness: the installed public headers never include it (the CTest
// design.include_walls enforces that), so a program using tcsb::tcsb sees the API and not these internals.
//
// The body's code runs here, on Impl's own members, so the operations and the per-step solve reach their data with no
// indirection more than before; Bullet's members of the body are reached through body_ (the TcSoftBody itself).
//
// How it stays inside Bullet's rules (docs/design.md, "The cut inside btSoftBody" and "Bullet internals that matter"):
//  * Bullet's node array is reserved once for every node of the tree, so no operation ever reallocates it and the
//    raw Node* held by links and DBVT leaves stay valid; our own references are indices.
//  * Nodes and links are removed by swap-with-last; the one node or link that moves is re-pointed through the
//    incidence lists, O(degree). Each node's DBVT leaf is inserted beside the leaf of the node it replaces and
//    removed with it, O(1) amortised (dbvt_local.h) rather than Bullet's O(log N) descent from the root.
//  * Link constants (m_rl, m_c1, m_c0) and inverse masses are written directly; the m_bUpdateRtCst flag, which would
//    reset every rest length to its stretched length, never fires.
//  * A balanced cut (neighbouring cut nodes at most one level apart) bounds every node's degree, so each operation
//    touches O(1) nodes and links whatever the size of the net.
//
// An operation's life: begin (refine or coarse) adds the new nodes beside the old ones. Each side carries half of
// the mass of the block, so total mass and linear momentum are conserved exactly; "tether" links hold the old node
// to the new ones. The old node's links to the neighbours fade out and the new nodes' links fade in over K steps by
// scaling m_c0 (the solver's correction scales with 1/m_c0; rest lengths never change). The end operation removes
// the old node with its links and hands its mass and momentum to the new nodes.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "../net/net.h"
#include "../softbody/compliant_solver.h"
#include "../softbody/cut_listener.h"
#include "../softbody/dbvt_local.h"
#include "../softbody/incidence_list.h"
#include "../softbody/op_sample.h"
#include "../softbody/solver_settings.h"
#include "../softbody/tc_settings.h"
#include "../softbody/tc_softbody.h"

namespace tcsb {

/// Which form an interface constraint takes: kMidpoint, the one described at InterfaceConstraint, on a tree whose
/// blocks rest at their centroids. On a tree whose blocks rest on their first leaf (RestPlacement::kVertex) a block's
/// node is its cell's corner, and the interface is the vertex kind an adaptive mesh has: of the two fine nodes, the
/// one in line with the coarse node (`kept`) stays joined to it by its handle as an ordinary link, and the other one
/// hangs. On the block's +x and +z sides it lies on the coarse cell's edge, and is held to the midpoint of that edge's
/// ends, the kept fine node and the node at the block's diagonal corner (kVertexFar); on its -x and -z sides its link
/// to the coarse side meets the block's side between the coarse node and the node at the block's corner along that
/// side, and is held at its rest distance to their midpoint (kVertexNear). The corner's node (`corner_leaf`'s) is found
/// at each step; where none rests there, a far constraint is skipped and a near one holds the hanging node to the
/// coarse node.
enum class InterfaceKind : std::uint8_t { kMidpoint, kVertexFar, kVertexNear };

/// With TcSettings::interfaces = kHanging, what replaces a fan: where the block of `coarse` meets the two finer
/// nodes `fine` across one of its sides (children of the block beside it), one distance constraint between the
/// coarse node and the fine nodes' midpoint, weights 1/2 each, at the rest distance between them. The fan's two
/// links stay in Bullet's link array as the constraint's handles — the operations fade, relabel and remove them as
/// they do every link, so the constraint follows the cut in O(degree) — with m_c0 = 0, which Bullet's link solver
/// skips (btSoftBody::PSolve_Links solves only m_c0 > 0); their blend weight is the constraint's.
struct InterfaceConstraint {
  TreeId coarse = kNoTreeNode;
  std::array<TreeId, 2> fine{kNoTreeNode, kNoTreeNode};
  std::array<std::int32_t, 2> links{-1, -1};  ///< the handles: links coarse-fine[0] and coarse-fine[1]
  btScalar rest = 0;  ///< rest distance from the coarse node to the fine nodes' midpoint (vertex kinds: InterfaceKind)
  btScalar stiffness = 1;  ///< kLST: the mean of the two levels' (interface_stiffness); vertex kinds the finer's
  InterfaceKind kind = InterfaceKind::kMidpoint;
  std::int8_t kept = -1;             ///< vertex kinds: which handle stays an ordinary link (the other fine node hangs)
  TreeId corner_leaf = kNoTreeNode;  ///< vertex kinds: the leaf at the block's corner the constraint reaches
};

class TcSoftBody::Impl {
 public:
  using Node = btSoftBody::Node;
  using Link = btSoftBody::Link;
  using Material = btSoftBody::Material;
  using Face = btSoftBody::Face;

  /// The body's state at the finest cut (TcSoftBody's constructor, which then gives it the body's start level).
  Impl(TcSoftBody& body, std::shared_ptr<const Net> net, const SolverSettings& solver, const TcSettings& settings);
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  TcSoftBody& body_;  ///< the btSoftBody this is the state of: its nodes, links, anchors, faces, materials
  TcSoftBody::LifetimeListener* lifetime_ = nullptr;  ///< told from TcSoftBody's destructor

  // ---- the public API's work (documented in tc_softbody.h; TcSoftBody forwards each call here) -------------
  const Net& net() const { return *net_; }
  const LodTree& tree() const { return net_->lod(); }
  const TcSettings& settings() const { return settings_; }
  const SolverSettings& solver() const { return solver_; }
  CutState state(TreeId id) const { return state_[static_cast<std::size_t>(id)]; }
  bool committed(TreeId id) const { return state(id) == CutState::kActive || state(id) == CutState::kArriving; }
  int bullet_index(TreeId id) const { return record(id).bullet; }
  TreeId tree_id(int index) const { return tree_of_[static_cast<std::size_t>(index)]; }
  const IncidenceList& incidence(TreeId id) const { return incidence_[static_cast<std::size_t>(id)]; }
  std::span<const CutState> states() const { return state_; }
  std::span<const std::int32_t> bullet_indices() const { return bullet_; }
  std::span<const TreeId> tree_ids() const { return tree_of_; }
  std::span<const CutLink> cut_links() const { return link_meta_; }
  LinkRole link_role(int link) const { return link_meta_[static_cast<std::size_t>(link)].role; }
  double simulated_mass(TreeId id) const { return record(id).sim_mass; }
  int node_count() const { return body_.m_nodes.size(); }
  int link_count() const { return body_.m_links.size(); }
  int committed_count() const { return committed_count_; }
  int interpolations() const { return static_cast<int>(inflight_.size()); }
  /// The interface constraints (hanging interfaces only; empty with the paper's fans).
  std::span<const InterfaceConstraint> interface_constraints() const { return interfaces_; }
  /// Times an append found Bullet's link array full and it had to grow (expected: never).
  int link_reallocations() const { return link_reallocations_; }

  OpCheck can_refine(TreeId id) const;
  OpCheck can_coarsen(TreeId parent) const;
  bool anchored(TreeId id) const;
  void begin_refine(TreeId id);
  void begin_coarse(TreeId parent);
  int coarsen_to_level(int level);
  void advance_blends(OrderSettling settling = OrderSettling::kNow);
  void simulate_step(btScalar dt);
  void solve_constraints();
  void move_pins(const btVector3& offset, btScalar dt);
  const btVector3& pin_offset() const { return pin_offset_; }
  btVector3 pin_position(TreeId id) const { return record(id).rest_position() + pin_offset_; }
  void enable_faces();
  bool faces_enabled() const { return faces_enabled_; }
  void refresh_faces();
  /// Times refresh_faces() rebuilt them.
  int face_rebuilds() const { return face_rebuilds_; }

  /// Receives every operation's timing (may be null).
  void set_op_sink(OpSink* sink) { sink_ = sink; }
  void set_cut_listener(CutListener* listener) { listener_ = listener; }

  void restore_order();
  void settle_order();
  /// Nodes and links moved by operations since the arrays were last in order (appended, or moved into a hole).
  int displaced() const { return displaced_; }
  /// Times restore_order() has run (by advance_blends() or a direct call).
  int order_restorations() const { return order_restorations_; }
  /// Builds the node DBVT afresh, as a plain body's is built (bullet_setup.h, insert_node_leaves: every node's leaf
  /// inserted from the root, in the same fixed shuffled order; each box is the one Bullet's own update would give
  /// the node now: its position and the margin, grown by the update margin and stretched along its velocity),
  /// after freeing the old tree and giving the freed memory back to malloc's free lists in one piece, so the new tree
  /// lies in one compact region. The tree takes no part in the physics (collisions are off), so positions, velocities
  /// and every invariant are unchanged. O(N log N); advance_blends() calls it only after the body has shrunk by the
  /// factor TcSettings::kDbvtRebuildShrink since the last build, so it costs amortised O(log N) per node removed and
  /// nothing at a fixed compression.
  void rebuild_node_dbvt();
  /// Times rebuild_node_dbvt() has run.
  int dbvt_rebuilds() const { return dbvt_rebuilds_; }

  Validation validate() const;

  /// Local deformation at a simulated node as child placement uses it: local_affine_fit(id), or the
  /// identity-in-plane [[1,0],[0,0],[0,1]] under rigid placement. O(degree).
  Eigen::Matrix<double, 3, 2> deformation(TreeId id) const;
  Eigen::Matrix<double, 3, 2> local_affine_fit(TreeId id) const;

  /// Whether links above level 0 use their level's calibrated stiffness (TcSettings::level_stiffness).
  bool calibrated() const { return !level_materials_.empty(); }
  /// The material a link between tree nodes a and b uses: the solver's (Bullet's m_materials[0]) when uncalibrated
  /// or both are leaves, else the one of the coarser endpoint's level. O(1).
  Material* link_material(TreeId a, TreeId b) const;

  Eigen::Vector3d linear_momentum() const;
  double total_mass() const;

  // ---- the rest: what the operations, the solve, the faces, the order and validate() share ----------------
  /// What the operations read and write of one tree node besides its state and incidence list, in 32 bytes: a node
  /// costs them one cache line, where separate arrays (Bullet index, rest, carried mass, operation, and the inverse
  /// mass in Bullet's node) cost five. Cache lines, not instructions, are what an operation's time grows with on a
  /// large net (tc_prefetch.cpp).
  struct alignas(32) NodeRecord {
    btScalar rest[3] = {0, 0, 0};  ///< rest position, in Bullet's precision
    /// Bullet's m_im of the node while simulated (0 when pinned), kept equal to it so that link constants are
    /// computed from here instead of from a neighbour's Bullet node, which is one more line per neighbour.
    btScalar inv_mass = 0;
    std::int32_t op = -1;  ///< operation it is a subject of, or -1
    /// Bullet index, or -1: the same as bullet_[id], which stays as a flat array for the feedback stage's readers
    /// (CutView); validate() checks that the two agree.
    std::int32_t bullet = -1;
    double sim_mass = 0;  ///< carried mass while simulated, kg
    btVector3 rest_position() const { return {rest[0], rest[1], rest[2]}; }
  };
  static_assert(sizeof(NodeRecord) == 32, "two records per cache line");

  struct Op {
    OpKind kind = OpKind::kRefine;  ///< kRefine or kCoarse
    TreeId parent = kNoTreeNode;    ///< the refined node, or the coarse's new node
    std::int32_t step = 0;          ///< blend steps done
    std::int32_t slot = -1;         ///< position in inflight_
  };

  // ---- validate(): one check per invariant, each reporting every break it finds (tc_validate.cpp) ------------
  using ProblemSink = std::function<void(const std::string&)>;
  /// The world around the body: no dirty-constants flag, a TcSoftBodySolver where one is needed, the node array
  /// reserved for the whole tree, the world's own info in a collision world.
  void validate_world_setup(const ProblemSink& fail) const;
  /// Every anchor holds a simulated node of this body, marked attached, and can be solved.
  void validate_anchors(const ProblemSink& fail) const;
  /// Bullet's nodes and the cut map onto each other both ways; one DBVT leaf per node; collision flags as the
  /// arrival rule says; finite positions and velocities.
  void validate_node_mapping(const ProblemSink& fail) const;
  /// Masses lumped as the cut says (block masses or masses that follow the cut), inverse masses matching, pins on
  /// their pins, the total conserved.
  void validate_masses(const ProblemSink& fail) const;
  /// "node I (tree ID)", how the node checks name a simulated node.
  std::string simulated_node_name(int index) const;
  /// Links consistent with the cut: endpoints, rest lengths, materials and constants as their roles say.
  void validate_link_constants(const ProblemSink& fail) const;
  /// The interface constraints: handles, siblings, kind, rest distances and stiffness, one per coarse side.
  void validate_interfaces(const ProblemSink& fail) const;
  /// With hanging interfaces, no fan left unpaired: every fan is one interface constraint.
  void validate_no_unpaired_fans(const ProblemSink& fail) const;
  /// The committed cut's faces as tree-node triples, in the order enable_faces() builds them (tc_faces.cpp);
  /// `owner` is scratch (one entry per leaf).
  void cut_faces(std::vector<std::array<TreeId, 3>>& out, std::vector<TreeId>& owner) const;
  /// cut_faces()' triples: those refresh_faces() built the faces from while they are current (no rebuild pending),
  /// else computed into `out` (`owner` its scratch). Either way the same triples in the same order.
  const std::vector<std::array<TreeId, 3>>& current_cut_faces(std::vector<std::array<TreeId, 3>>& out,
                                                              std::vector<TreeId>& owner) const;
  /// The faces: over the committed cut's nodes, as enable_faces() builds them.
  void validate_faces(const ProblemSink& fail) const;
  /// The incidence lists hold exactly Bullet's link set.
  void validate_incidence(const ProblemSink& fail) const;
  /// The committed cut and the old cut are each a cut: every leaf covered exactly once.
  void validate_cut_partition(const ProblemSink& fail) const;
  /// The committed cut is balanced and linked to exactly its neighbours; its node count is current.
  void validate_committed_links(const ProblemSink& fail) const;
  /// The operations in flight own their subjects and are inside their blend; the link array never grew.
  void validate_operations(const ProblemSink& fail) const;

  // node and link primitives, all O(1) or O(degree)
  int add_node(TreeId id, const btVector3& x, const btVector3& v, TreeId beside);
  void remove_node(TreeId id);
  /// Re-points every Bullet anchor (m_anchors: appendAnchor's, or an application's own) that holds the node at `from`
  /// to `to`, where that node now lives: a node moved in Bullet's array keeps its anchors. O(anchors).
  void follow_anchors(const Node* from, Node* to);
  /// Before `from` leaves Bullet at an end operation: its anchors (an application anchored it while the operation
  /// blended) go to `to`, the node of the committed cut that takes its place, with the same attachment point on the
  /// rigid body, so the cloth stays attached. O(anchors).
  void hand_over_anchors(TreeId from, TreeId to);
  /// The child of `parent` whose Bullet node lies nearest the parent's (both simulated: a refine ending). O(children).
  TreeId nearest_child(TreeId parent) const;
  int add_link(TreeId a, TreeId b, LinkRole role, std::int32_t op);
  void remove_link(int link);
  /// With hanging interfaces, after add_link: when the new link and one already there from the same coarse node to
  /// the sibling of its fine end, in the same role and operation, form a fan, makes them one interface constraint.
  /// O(degree of the coarse node).
  void pair_into_interface(int link);
  /// Before remove_link: dissolves the link's interface constraint (swap-with-last), the partner becoming a plain
  /// link again. O(1).
  void dissolve_interface(int link);
  /// A level's link stiffness: its calibrated one, or the solver's when uncalibrated.
  btScalar level_stiffness(int level) const;
  /// The material a link takes: link_material() of its endpoints; with vertex_edges(), the finer of the levels of the
  /// two cells of the committed cut the link is the edge between (docs/design.md, "Interfaces between levels").
  /// O(levels).
  Material* edge_material(int link) const;
  /// Whether links take edge_material()'s rule: calibrated, hanging interfaces, a tree resting on first leaves (with
  /// the paper's fans the rule made a first-leaf tree err more: docs/investigations/cut-masses.md).
  bool vertex_edges() const {
    return calibrated() && settings_.interfaces == Interfaces::kHanging && tree().placement() == RestPlacement::kVertex;
  }
  /// On a tree resting on first leaves, makes a new constraint the vertex kind (InterfaceKind). O(1).
  void make_vertex_interface(InterfaceConstraint& c) const;
  /// The stiffness of an interface constraint between cloth of `fine_level` and the level above: the solver's when
  /// uncalibrated, else the mean of the two levels' calibrated stiffnesses.
  btScalar interface_stiffness(int fine_level) const;
  /// Projects every interface constraint once (one position iteration's share), with the constants
  /// prepare_interfaces() computed for this step.
  void project_interfaces();
  /// The same on the compliant material's double positions (one small step's share).
  void project_interfaces(SubstepPositions& x);
  /// Per step: each interface constraint's nodes and constant (stiffness, blend weight and inverse masses as they
  /// are now).
  void prepare_interfaces();
  void set_simulated_mass(TreeId id, double mass);

  // ---- masses that follow the cut (tc_cut_masses.cpp; TcSettings::masses = Masses::kCut) ----------------------
  /// Per tree node: what its leaves' masses give, by the bilinear weights between its node and the nodes at its
  /// far corners, to its own node and to each far corner; and the leaf its node rests on.
  struct CornerShares {
    std::array<double, 4> share{};          ///< own, the +x corner, the +z corner, the diagonal corner, kg
    std::int32_t x = 0, z = 0;              ///< the leaf the node rests on
    std::int32_t next_x = -1, next_z = -1;  ///< the leaf column and row of the far corners; -1 past the net
  };
  bool cut_masses() const { return settings_.masses == Masses::kCut; }
  /// Fills corner_shares_ once, O(T log T). Throws unless the tree's blocks rest on their first leaf.
  void build_corner_shares();
  /// The node of the committed cut (`committed`) or of the old cut (active or leaving) whose block holds leaf (x, z),
  /// which must be on the grid (unchecked: the climbs run a dozen times for each node a ring settles). O(levels).
  TreeId holding(int x, int z, bool committed) const;
  /// holding(x, z, true) and holding(x, z, false) from one climb (holding() reads one of them). O(levels).
  std::array<TreeId, 2> holders(int x, int z) const;
  /// The masses `id` carries in the committed and in the old cut: in each its leaves' own share, the shares of its
  /// far corners that fall on no node of the cut, and the shares of the blocks whose far corner it rests on; 0 in a
  /// cut it is not in. O(levels).
  std::array<double, 2> cut_mass(TreeId id) const;
  /// What a simulated node carries: the mean of its masses in the old and the committed cut, so that an operation's
  /// two sides each carry half, as with block masses. O(levels).
  double target_mass(TreeId id) const {
    const std::array<double, 2> mass = cut_mass(id);
    return 0.5 * (mass[0] + mass[1]);
  }
  /// Every node of `nodes` (ring_nodes() of an operation's block) goes to target_mass(), the mass moving from the
  /// nodes that lose it to those that gain it with its momentum, and their links' constants follow. O(nodes x levels).
  void settle_cut_masses(const std::vector<TreeId>& nodes);
  /// After an operation on `block`: the simulated nodes whose masses or links' materials it can have changed (the
  /// block's nodes and those holding the ring of leaves around it, in either cut) into settle_scratch_. O(block
  /// perimeter x levels).
  const std::vector<TreeId>& ring_nodes(TreeId block);
  /// After every operation on `block`: with masses that follow the cut they are settled, and with vertex_edges()
  /// every link of the ring's nodes is given edge_material() (its constant rewritten where that changed); else
  /// nothing.
  void settle_ring(TreeId block);
  /// Writes a tree node's Bullet index (or -1) to its record and to the bullet_ mirror together.
  void set_bullet_index(TreeId id, std::int32_t index);
  NodeRecord& record(TreeId id) { return record_[static_cast<std::size_t>(id)]; }
  const NodeRecord& record(TreeId id) const { return record_[static_cast<std::size_t>(id)]; }
  /// Bullet's inverse mass for carrying `mass`: 0 when the node is pinned.
  btScalar inverse_mass(TreeId id, double mass) const;
  /// Writes a link's constant from its endpoints' inverse masses and its blend weight (counts nothing); under the
  /// compliant material with the link's compliance too (link_stiffness()).
  void write_link_constant(int link);
  // ---- the compliant material (tc_compliance.cpp) ------------------------------------------------------------
  /// The membrane rule's stiffness of a straight segment between leaves (xa, za) and (xb, zb) along one axis, from
  /// the cells of the committed cut (or of the old cut) on either side of it, N/m (material.h). O(levels): a balanced
  /// cut puts at most two cells beside a segment on each side.
  double segment_stiffness(int xa, int za, int xb, int zb, bool committed) const;
  /// A link's stiffness under the compliant material: segment_stiffness() between its endpoints' rest leaves, in the
  /// cut it belongs to (the committed one, or the old one for a link leaving with it); a link not along an axis (an
  /// operation's tether) carries the stiffness of a link inside a grid. O(levels).
  double link_stiffness(int link) const;
  /// The stiffness of the segment an interface constraint stands for (InterfaceKind), N/m; infinity for the
  /// far kind, which holds its hanging node on the coarse edge as an interpolated point. O(levels).
  double interface_link_stiffness(const InterfaceConstraint& c, TreeId corner) const;
  /// The compliant constant of a constraint with generalised inverse mass `w`, stiffness `k` and blend `alpha`.
  btScalar compliant_constant(btScalar w, double k, double alpha) const;
  /// write_link_constant, counted as operation work.
  void refresh_link_constant(int link);
  void refresh_incident_constants(TreeId id);
  /// Whether the link is the handle a vertex interface keeps as an ordinary link (InterfaceConstraint::kept).
  bool kept_handle(int link) const {
    const std::int32_t i = link_meta_[static_cast<std::size_t>(link)].interface;
    if (i < 0) return false;
    const InterfaceConstraint& c = interfaces_[static_cast<std::size_t>(i)];
    return c.kept >= 0 && c.links[static_cast<std::size_t>(c.kept)] == link;
  }
  double blend_alpha(const CutLink& meta) const;
  /// (steps done + 1) / (K + 1): the weight of what an operation brings in.
  double op_progress(const Op& op) const;
  btScalar rest_length(TreeId a, TreeId b) const;

  std::int32_t new_op(OpKind kind, TreeId parent);
  void end_op(std::int32_t op);
  void end_refine(const Op& op);
  void end_coarse(const Op& op);
  /// The end operations' shared steps: links that finished fading in become steady; a node that stays carries its
  /// full mass and belongs to no operation; a node that goes leaves Bullet and the cut (it must have no links left).
  void make_faded_in_links_steady(TreeId id);
  void settle_in_cut(TreeId id, double mass);
  void retire_from_cut(TreeId id);
  /// Starts loading the cache lines an operation on the block of `id` will touch (tc_prefetch.cpp). No effect on
  /// results; O(degree). Does nothing in a build with the CMake option TCSB_OP_PREFETCH off.
  void prefetch_footprint(TreeId id) const;
  /// Starts loading what removing the links incident to `ids` will touch beyond them: the other endpoints'
  /// incidence lists, and the incidence lists of the links at the end of the array that the swap-with-last removals
  /// will move (tc_prefetch.cpp). No effect on results; O(links removed).
  void prefetch_link_removals(std::span<const TreeId> ids) const;
  /// committed(id), counted as one tree record probed: the membership test an operation's neighbour walk makes.
  bool probe_committed(TreeId id) {
    ++work_.tree_records;
    return committed(id);
  }
  /// Now, in nanoseconds, for an operation's sample; 0 without a sink: nobody collects, so nothing reads the clock.
  std::int64_t op_clock() const;
  /// Hands an operation's sample to the sink and the change to the cut listener, whichever are set.
  void emit(OpKind kind, TreeId block, std::int64_t node_ns, std::int64_t link_ns);
  btVector3 place_child(TreeId parent, TreeId child, const btVector3& parent_x,
                        const Eigen::Matrix<double, 3, 2>& deformation) const;

  std::shared_ptr<const Net> net_;
  SolverSettings solver_;
  TcSettings settings_;
  double total_mass_ = 0;
  btVector3 pin_offset_{0, 0, 0};  // move_pins()

  std::vector<CutState> state_;           // per tree node
  std::vector<std::int32_t> bullet_;      // per tree node: Bullet index or -1 (as record_, for CutView's readers)
  std::vector<IncidenceList> incidence_;  // per tree node
  std::vector<NodeRecord> record_;        // per tree node
  std::vector<TreeId> tree_of_;           // per Bullet node
  std::vector<CutLink> link_meta_;        // per Bullet link
  std::vector<InterfaceConstraint> interfaces_;  // hanging interfaces only
  /// An interface constraint as one step solves it: its nodes, rest distance squared and constant (0: skipped).
  struct PreparedInterface {
    Node* coarse = nullptr;
    Node* fine[2] = {nullptr, nullptr};
    btScalar c0 = 0, c1 = 0;
    /// The three nodes' m_im, which no solve changes: read here, the projection touches one cache line of a node
    /// (m_x) instead of two (a Node is 256 bytes, m_im 96 bytes after m_x).
    std::array<btScalar, 3> inverse_mass{};
    double compliance = 0;  ///< the compliant material's alpha~ that c0 stands for (compliance_in_constant)
  };
  std::vector<PreparedInterface> prepared_interfaces_;  // per step, reused
  /// prepared_interfaces_ still holds what prepare_interfaces() would compute: no node, link or mass changed since,
  /// and no operation was blending then. Cleared by add_node, remove_node, add_link, remove_link,
  /// set_simulated_mass and restore_order.
  bool interfaces_prepared_ = false;
  SubstepPositions substep_positions_;  // the compliant material's small steps (compliant_solver.h), reused
  /// Per LOD level, the material its links use (level 0: the solver's); empty when uncalibrated. Owned by Bullet
  /// (appendMaterial; freed with the body), made once at construction: materials cannot be freed before the body.
  std::vector<Material*> level_materials_;
  DbvtNodeCache dbvt_nodes_;  // spare nodes for the node DBVT's local edits
  bool faces_enabled_ = false;
  bool faces_stale_ = false;  // the cut or the node array changed since the faces were built
  int face_rebuilds_ = 0;
  std::vector<std::array<TreeId, 3>> face_scratch_;  // cut_faces()' output, kept to reuse the room
  std::vector<btScalar> area_scratch_;               // per Bullet node: summed face areas, then the count
  std::vector<TreeId> owner_scratch_;                // per leaf: the committed node whose block holds it
  int displaced_ = 0;  // nodes and links out of order since restore_order() (see displaced())
  int order_restorations_ = 0;
  int dbvt_rebuilds_ = 0;
  int dbvt_peak_nodes_ = 0;  // the most nodes simulated since the node DBVT was last built
  /// restore_order()'s scratch, kept to reuse the room: a permutation (new -> old), its inverse, one slot per
  /// spatial rank of the tree, and a bit per rank the cut holds.
  std::vector<std::int32_t> order_, position_, rank_slots_;
  std::vector<std::uint64_t> rank_bits_;
  std::vector<Op> ops_;  // operation pool
  std::vector<std::int32_t> free_ops_;
  std::vector<std::int32_t> inflight_;  // operations blending
  int committed_count_ = 0;
  int link_reallocations_ = 0;
  OpSink* sink_ = nullptr;
  CutListener* listener_ = nullptr;
  /// The running operation's work (OpWork's definitions): zeroed when an operation starts, emitted when it ends.
  /// Primitives count into it whenever they run; between operations (the blend ramp) nothing reads it.
  OpWork work_;
  std::vector<CornerShares> corner_shares_;  // per tree node, with masses that follow the cut
  std::vector<TreeId> settle_scratch_;       // ring_nodes()' nodes, kept to reuse the room
  std::vector<double> settle_targets_;       // settle_cut_masses()' targets, likewise
};

}  // namespace tcsb
