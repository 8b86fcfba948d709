// TcSoftBody's four TreeCut operations (paper §3.3–3.4) and their blending. Every function here touches one
// block of the tree and its neighbours: O(1) in the size of the net.
#include <Eigen/Dense>
#include <array>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "net/cut_adjacency.h"
#include "softbody/affine_fit.h"
#include "softbody/tc_softbody_impl.h"
#include "softbody/vector_conversion.h"

namespace tcsb {

namespace {
std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
/// Whether `n` is one of the block's children, answered from the block's own record: reading n's record instead
/// would be one more cache miss per neighbour.
bool is_child(const LodNode& block, TreeId n) {
  for (int i = 0; i < block.child_count; ++i)
    if (block.children[static_cast<std::size_t>(i)] == n) return true;
  return false;
}
}  // namespace

// ---- admission -----------------------------------------------------------------------------------------------

bool TcSoftBody::Impl::anchored(TreeId id) const {
  if (body_.m_anchors.size() == 0) return false;  // the usual case, without reading the node's record
  const int index = bullet_index(id);
  if (index < 0) return false;
  for (int a = 0; a < body_.m_anchors.size(); ++a)
    if (body_.m_anchors[a].m_node == &body_.m_nodes[index]) return true;
  return false;
}

TreeId TcSoftBody::Impl::nearest_child(TreeId parent) const {
  const LodNode& node = tree().node(parent);
  const btVector3& x = body_.m_nodes[record(parent).bullet].m_x;
  TreeId best = node.children[0];
  btScalar best_d2 = SIMD_INFINITY;
  for (int i = 0; i < node.child_count; ++i) {
    const TreeId c = node.children[static_cast<std::size_t>(i)];
    if (record(c).bullet < 0) continue;
    const btScalar d2 = (body_.m_nodes[record(c).bullet].m_x - x).length2();
    if (d2 < best_d2) best_d2 = d2, best = c;
  }
  return best;
}

OpCheck TcSoftBody::Impl::can_refine(TreeId id) const {
  OpCheck check;
  const LodNode& node = tree().node(id);
  if (state(id) != CutState::kActive || node.is_leaf() || anchored(id)) return check;
  bool neighbours_ready = true;
  const bool balanced = for_each_cut_neighbour(
      tree(), id, [this](TreeId n) { return committed(n); },
      [&](TreeId n) {
        if (state(n) != CutState::kActive) neighbours_ready = false;    // an operation is blending next door
        if (tree().node(n).level > node.level) check.refine_first = n;  // children would be two levels apart
      });
  check.ok = balanced && neighbours_ready && check.refine_first == kNoTreeNode;
  if (!neighbours_ready) check.refine_first = kNoTreeNode;
  return check;
}

OpCheck TcSoftBody::Impl::can_coarsen(TreeId parent) const {
  OpCheck check;
  const LodNode& node = tree().node(parent);
  if (state(parent) != CutState::kOff || node.is_leaf() || !node.simulable()) return check;
  for (int i = 0; i < node.child_count; ++i) {
    const TreeId child = node.children[static_cast<std::size_t>(i)];
    if (state(child) != CutState::kActive || anchored(child)) return check;
  }
  bool neighbours_ready = true;
  // Looking one level below the parent finds the neighbours of its children; anything finer makes the walk report
  // an unbalanced side, which is exactly the case where coarsening would leave neighbours two levels apart.
  const bool balanced = for_each_cut_neighbour(
      tree(), parent, [this](TreeId n) { return committed(n); },
      [&](TreeId n) {
        if (state(n) != CutState::kActive) neighbours_ready = false;
      });
  check.ok = balanced && neighbours_ready;
  return check;
}

// ---- placement -----------------------------------------------------------------------------------------------

Eigen::Matrix<double, 3, 2> TcSoftBody::Impl::deformation(TreeId id) const {
  // The paper places children rigidly and names deformation-aware placement as future work (§7).
  if (settings_.placement == Placement::kRigid) {
    Eigen::Matrix<double, 3, 2> f;
    f << 1, 0, 0, 0, 0, 1;
    return f;
  }
  return local_affine_fit(id);
}

Eigen::Matrix<double, 3, 2> TcSoftBody::Impl::local_affine_fit(TreeId id) const {
  // Least-squares affine map F (3x2) from rest offsets in the net's plane (x, z) to current offsets, fitted over
  // the node's neighbours: minimises sum |(x_n - x_p) - F (r_n - r_p)|^2.
  const btVector3& xp = body_.m_nodes[record(id).bullet].m_x;
  const btVector3 rp = record(id).rest_position();
  Eigen::Matrix2d rr = Eigen::Matrix2d::Zero();
  Eigen::Matrix<double, 3, 2> xr = Eigen::Matrix<double, 3, 2>::Zero();
  for (std::int32_t li : incidence_[static_cast<std::size_t>(id)]) {
    const CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
    const TreeId n = meta.other(id);
    const NodeRecord& rn = record(n);
    const btVector3 dr = rn.rest_position() - rp;
    const btVector3 dx = body_.m_nodes[rn.bullet].m_x - xp;
    const Eigen::Vector2d r(dr.x(), dr.z());
    rr += r * r.transpose();
    xr += to_eigen(dx) * r.transpose();
  }
  return solve_affine_fit(rr, xr);
}

btVector3 TcSoftBody::Impl::place_child(TreeId parent, TreeId child, const btVector3& parent_x,
                                        const Eigen::Matrix<double, 3, 2>& deformation) const {
  if (tree().node(child).pinned()) return pin_position(child);  // where the pins are now (moved along their path)
  const btVector3 d = record(child).rest_position() - record(parent).rest_position();
  if (settings_.placement == Placement::kRigid) return parent_x + d;
  return to_bullet(to_eigen(parent_x) + deformation * Eigen::Vector2d(d.x(), d.z()));
}

// ---- begin operations ----------------------------------------------------------------------------------------

std::int32_t TcSoftBody::Impl::new_op(OpKind kind, TreeId parent) {
  std::int32_t index;
  if (!free_ops_.empty()) {
    index = free_ops_.back();
    free_ops_.pop_back();
  } else {
    index = static_cast<std::int32_t>(ops_.size());
    ops_.emplace_back();
  }
  Op& op = ops_[static_cast<std::size_t>(index)];
  op.kind = kind;
  op.parent = parent;
  op.step = 0;
  op.slot = static_cast<std::int32_t>(inflight_.size());
  inflight_.push_back(index);
  return index;
}

void TcSoftBody::Impl::begin_refine(TreeId p) {
  const std::int64_t t0 = op_clock();
  prefetch_footprint(p);
  work_ = {.interior = neighbourhood_inside_net(tree(), p)};
  const LodNode& pn = tree().node(p);
  const std::int32_t op = new_op(OpKind::kRefine, p);
  const Node& parent_node = body_.m_nodes[record(p).bullet];
  const btVector3 xp = parent_node.m_x, vp = parent_node.m_v;
  ++work_.tree_records;  // p's LOD node, record and state
  ++work_.nodes;         // p's position and velocity
  const Eigen::Matrix<double, 3, 2> affine = deformation(p);
  if (settings_.placement != Placement::kRigid) {
    // local_affine_fit (const, also used outside operations) visits each link of p, its other endpoint's record
    // and its Bullet node.
    const int fitted = incidence_[static_cast<std::size_t>(p)].size();
    work_.links += fitted;
    work_.tree_records += fitted;
    work_.nodes += fitted;
  }
  // Children take the parent's velocity and half their mass; the parent keeps the other half. Total mass and
  // linear momentum are unchanged. (With masses that follow the cut the parent's mass is not its block's: the
  // children share its half as their blocks share the block, and settle_ring() then moves the rest.)
  const double parent_mass = record(p).sim_mass;
  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    ++work_.tree_records;  // c's LOD node, record and state
    record(c).sim_mass = cut_masses() ? 0.5 * parent_mass * (tree().node(c).mass / pn.mass) : 0.5 * tree().node(c).mass;
    add_node(c, place_child(p, c, xp, affine), vp, p);
    state_[static_cast<std::size_t>(c)] = CutState::kArriving;
    record(c).op = op;
  }
  set_simulated_mass(p, 0.5 * parent_mass);  // (with block masses parent_mass is pn.mass exactly)
  state_[static_cast<std::size_t>(p)] = CutState::kLeaving;
  record(p).op = op;
  committed_count_ += pn.child_count - 1;
  const std::int64_t t1 = op_clock();

  for (std::int32_t li : incidence_[static_cast<std::size_t>(p)]) {
    CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
    meta.role = LinkRole::kFadeOut;
    meta.op = op;
    refresh_link_constant(li);  // the parent's mass halved, and the link starts fading
  }
  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    // Children connect to each other at full strength (not blended) and to the committed neighbours touching
    // their block — the nearest of the parent's neighbours — fading in.
    ++work_.tree_records;  // the walk reads c's LOD node; each membership probe counts one more
    for_each_cut_neighbour(
        tree(), c, [this](TreeId n) { return probe_committed(n); },
        [&](TreeId n) {
          if (is_child(pn, n)) {
            if (c < n) add_link(c, n, LinkRole::kSteady, -1);
          } else {
            add_link(c, n, LinkRole::kFadeIn, op);
          }
        });
    add_link(p, c, LinkRole::kTether, op);
  }
  settle_ring(p);
  emit(OpKind::kRefine, p, t1 - t0, op_clock() - t1);
}

void TcSoftBody::Impl::begin_coarse(TreeId p) {
  const std::int64_t t0 = op_clock();
  prefetch_footprint(p);
  work_ = {.interior = neighbourhood_inside_net(tree(), p)};
  const LodNode& pn = tree().node(p);
  const std::int32_t op = new_op(OpKind::kCoarse, p);
  ++work_.tree_records;  // p's LOD node, record and state
  // The parent appears at its children's centre of mass with their mean velocity, carrying half their mass.
  // A block on the net's border rests on the border: it appears where its children's fit puts that point instead.
  Eigen::Vector3d weighted_x = Eigen::Vector3d::Zero(), momentum = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 4> child_x;
  double children_mass = 0;  // with block masses pn.mass, summed in the same order
  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    const Node& n = body_.m_nodes[record(c).bullet];
    const double m = record(c).sim_mass;
    children_mass += m;
    ++work_.tree_records;  // c's LOD node, record, state and incidence list
    ++work_.nodes;         // c's position and velocity
    child_x[static_cast<std::size_t>(i)] = to_eigen(n.m_x);
    weighted_x += m * child_x[static_cast<std::size_t>(i)];
    momentum += m * to_eigen(n.m_v);
  }
  btVector3 xp = pn.pinned() ? pin_position(p) : to_bullet(weighted_x / children_mass);
  if (const std::optional<Eigen::Vector3d> border = border_arrival(tree(), p, child_x)) xp = to_bullet(*border);
  record(p).sim_mass = 0.5 * children_mass;
  add_node(p, xp, to_bullet(momentum / children_mass), pn.children[0]);
  state_[static_cast<std::size_t>(p)] = CutState::kArriving;
  record(p).op = op;
  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    set_simulated_mass(c, 0.5 * record(c).sim_mass);
    state_[static_cast<std::size_t>(c)] = CutState::kLeaving;
    record(c).op = op;
  }
  committed_count_ += 1 - pn.child_count;
  const std::int64_t t1 = op_clock();

  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    for (std::int32_t li : incidence_[static_cast<std::size_t>(c)]) {
      CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
      const TreeId other = meta.other(c);
      // Links among the children hold at full strength until the end; links to the outside fade out.
      meta.role = is_child(pn, other) ? LinkRole::kDoomed : LinkRole::kFadeOut;
      meta.op = op;
      refresh_link_constant(li);
    }
  }
  ++work_.tree_records;  // the walk reads p's LOD node; each membership probe counts one more
  for_each_cut_neighbour(
      tree(), p, [this](TreeId n) { return probe_committed(n); },
      [&](TreeId n) { add_link(p, n, LinkRole::kFadeIn, op); });
  for (int i = 0; i < pn.child_count; ++i) add_link(p, pn.children[static_cast<std::size_t>(i)], LinkRole::kTether, op);
  settle_ring(p);
  emit(OpKind::kCoarse, p, t1 - t0, op_clock() - t1);
}

int TcSoftBody::Impl::coarsen_to_level(int level) {
  const LodTree& lod = tree();
  for (int l = 1; l <= level && l < lod.level_count(); ++l) {
    for (bool began = true; began;) {
      began = false;
      for (int gy = 0; gy < lod.level_height(l); ++gy)
        for (int gx = 0; gx < lod.level_width(l); ++gx) {
          const TreeId id = lod.at(l, gx, gy);
          if (can_coarsen(id).ok) {
            begin_coarse(id);
            began = true;
          }
        }
      // No simulated time passes: the blends only move the link constants to their end.
      while (interpolations() > 0) advance_blends();
    }
  }
  return committed_count();
}

// ---- blending and end operations -----------------------------------------------------------------------------

void TcSoftBody::Impl::advance_blends(OrderSettling settling) {
  // Backwards, so ending an operation (which moves the last in-flight entry into its slot) skips nothing.
  for (std::size_t i = inflight_.size(); i-- > 0;) {
    const std::int32_t index = inflight_[i];
    Op& op = ops_[static_cast<std::size_t>(index)];
    if (++op.step >= settings_.blend_steps) {
      end_op(index);
      continue;
    }
    const LodNode& pn = tree().node(op.parent);
    const auto ramp = [&](TreeId subject) {
      for (std::int32_t li : incidence_[static_cast<std::size_t>(subject)]) {
        const CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
        if (meta.op == index && (meta.role == LinkRole::kFadeIn || meta.role == LinkRole::kFadeOut))
          refresh_link_constant(li);
      }
    };
    ramp(op.parent);
    for (int c = 0; c < pn.child_count; ++c) ramp(pn.children[static_cast<std::size_t>(c)]);
  }
  const bool large = settings_.restore_order && body_.m_nodes.size() >= settings_.restore_order_min_nodes;
  if (large) dbvt_peak_nodes_ = std::max(dbvt_peak_nodes_, body_.m_nodes.size());
  const bool rebuild =
      large && settings_.rebuild_dbvt && dbvt_peak_nodes_ >= TcSettings::kDbvtRebuildShrink * body_.m_nodes.size();
  // The rebuilt tree takes its leaves in the node array's order: that order must be the settled one.
  if (settings_.exact_order && (settling == OrderSettling::kNow || rebuild))
    settle_order();
  else if (!settings_.exact_order && large &&
           displaced_ > TcSettings::kReorderFraction * static_cast<double>(body_.m_nodes.size() + body_.m_links.size()))
    restore_order();
  if (rebuild) rebuild_node_dbvt();
}

void TcSoftBody::Impl::end_op(std::int32_t index) {
  const Op op = ops_[static_cast<std::size_t>(index)];
  if (op.kind == OpKind::kRefine)
    end_refine(op);
  else
    end_coarse(op);
  // Drop it from the in-flight list by swap-with-last.
  const std::int32_t moved = inflight_.back();
  inflight_[static_cast<std::size_t>(op.slot)] = moved;
  ops_[static_cast<std::size_t>(moved)].slot = op.slot;
  inflight_.pop_back();
  ops_[static_cast<std::size_t>(index)].slot = -1;
  free_ops_.push_back(index);
}

void TcSoftBody::Impl::end_refine(const Op& op) {
  const std::int64_t t0 = op_clock();
  const TreeId p = op.parent;
  const LodNode& pn = tree().node(p);
  prefetch_link_removals(std::span<const TreeId>(&p, 1));
  work_ = {.interior = neighbourhood_inside_net(tree(), p)};
  ++work_.tree_records;                                       // p's LOD node, record and incidence list
  while (incidence_[static_cast<std::size_t>(p)].size() > 0)  // faded-out links and tethers
    remove_link(incidence_[static_cast<std::size_t>(p)][0]);
  for (int i = 0; i < pn.child_count; ++i) make_faded_in_links_steady(pn.children[static_cast<std::size_t>(i)]);
  const std::int64_t t1 = op_clock();

  // The parent's half of the mass and its momentum go to the children in proportion to their masses.
  const Eigen::Vector3d vp = to_eigen(body_.m_nodes[record(p).bullet].m_v);
  ++work_.nodes;  // p's velocity
  // (With masses that follow the cut, in proportion to the halves they carry; settle_ring() follows.)
  double children_half = 0;
  if (cut_masses())
    for (int i = 0; i < pn.child_count; ++i) children_half += record(pn.children[static_cast<std::size_t>(i)]).sim_mass;
  const double parent_share = record(p).sim_mass / (cut_masses() ? children_half : pn.mass);
  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    ++work_.tree_records;  // c's LOD node and record
    ++work_.nodes;         // c's velocity
    const double full = cut_masses() ? (1 + parent_share) * record(c).sim_mass : tree().node(c).mass;
    Node& n = body_.m_nodes[record(c).bullet];
    const double received = parent_share * (cut_masses() ? record(c).sim_mass : full);
    if (!tree().node(c).pinned()) n.m_v = to_bullet((record(c).sim_mass * to_eigen(n.m_v) + received * vp) / full);
    settle_in_cut(c, full);
  }
  if (anchored(p)) hand_over_anchors(p, nearest_child(p));
  retire_from_cut(p);
  const std::int64_t t2 = op_clock();

  for (int i = 0; i < pn.child_count; ++i) refresh_incident_constants(pn.children[static_cast<std::size_t>(i)]);
  settle_ring(p);
  const std::int64_t t3 = op_clock();
  emit(OpKind::kEndRefine, p, t2 - t1, (t1 - t0) + (t3 - t2));
}

void TcSoftBody::Impl::end_coarse(const Op& op) {
  const std::int64_t t0 = op_clock();
  const TreeId p = op.parent;
  const LodNode& pn = tree().node(p);
  prefetch_link_removals(std::span<const TreeId>(pn.children.data(), static_cast<std::size_t>(pn.child_count)));
  work_ = {.interior = neighbourhood_inside_net(tree(), p)};
  ++work_.tree_records;  // p's LOD node and record
  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    ++work_.tree_records;                                       // c's incidence list and record
    while (incidence_[static_cast<std::size_t>(c)].size() > 0)  // faded-out, doomed and tether links
      remove_link(incidence_[static_cast<std::size_t>(c)][0]);
  }
  make_faded_in_links_steady(p);
  const std::int64_t t1 = op_clock();

  // The children's halves of the mass and their momentum go to the parent.
  Node& parent_node = body_.m_nodes[record(p).bullet];
  ++work_.nodes;  // p's velocity
  Eigen::Vector3d momentum = record(p).sim_mass * to_eigen(parent_node.m_v);
  double mass = record(p).sim_mass;
  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    ++work_.nodes;  // c's velocity
    momentum += record(c).sim_mass * to_eigen(body_.m_nodes[record(c).bullet].m_v);
    mass += record(c).sim_mass;
  }
  if (!cut_masses()) mass = pn.mass;  // the same sum, kept exact
  if (!pn.pinned()) parent_node.m_v = to_bullet(momentum / mass);
  settle_in_cut(p, mass);
  for (int i = 0; i < pn.child_count; ++i) {
    const TreeId c = pn.children[static_cast<std::size_t>(i)];
    if (anchored(c)) hand_over_anchors(c, p);
    retire_from_cut(c);
  }
  const std::int64_t t2 = op_clock();

  refresh_incident_constants(p);
  settle_ring(p);
  const std::int64_t t3 = op_clock();
  emit(OpKind::kEndCoarse, p, t2 - t1, (t1 - t0) + (t3 - t2));
}

void TcSoftBody::Impl::make_faded_in_links_steady(TreeId id) {
  for (std::int32_t li : incidence_[static_cast<std::size_t>(id)]) {
    CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
    ++work_.links;
    if (meta.role == LinkRole::kFadeIn) {  // (its interface constraint, if any, stays)
      meta.role = LinkRole::kSteady;
      meta.op = -1;
    }
  }
}

void TcSoftBody::Impl::settle_in_cut(TreeId id, double mass) {
  set_simulated_mass(id, mass);
  state_[static_cast<std::size_t>(id)] = CutState::kActive;
  // Its collision shape joins, unless an application anchored it meanwhile (appendAnchor sets the same flag).
  if (!settings_.arrivals_collide && !anchored(id)) body_.m_nodes[record(id).bullet].m_battach = 0;
  record(id).op = -1;
}

void TcSoftBody::Impl::retire_from_cut(TreeId id) {
  remove_node(id);
  record(id).sim_mass = 0;
  state_[static_cast<std::size_t>(id)] = CutState::kOff;
  record(id).op = -1;
}

std::int64_t TcSoftBody::Impl::op_clock() const { return sink_ != nullptr ? now_ns() : 0; }

void TcSoftBody::Impl::emit(OpKind kind, TreeId block, std::int64_t node_ns, std::int64_t link_ns) {
  if (listener_ != nullptr) listener_->cut_changed(kind, block);
  if (sink_ == nullptr) return;
  sink_->record({kind, static_cast<std::int32_t>(node_ns), static_cast<std::int32_t>(link_ns), body_.m_nodes.size(),
                 body_.m_links.size(), work_});
}

}  // namespace tcsb
