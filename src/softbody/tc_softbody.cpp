// TcSoftBody::Impl: construction and the O(1)/O(degree) node and link primitives every operation is made of.
#include "softbody/tc_softbody_impl.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "softbody/bullet_setup.h"
#include "softbody/dbvt_local.h"
#include "softbody/pin_motion.h"
#include "softbody/tc_softbody_solver.h"
#include "softbody/vector_conversion.h"

namespace tcsb {

namespace {

/// Writes every element of an array's reserved room once (constructs copies of `fill`, then drops them), so the
/// operations that later append there never take a page fault on untouched memory in the middle of a step.
template <class Array, class T>
void touch_reserved(Array& array, const T& fill) {
  const auto size = array.size();
  array.resize(array.capacity(), fill);
  array.resize(size, fill);  // (not the one-argument form: Bullet's default-constructs an uninitialised Node)
}

}  // namespace

TcSoftBody::Impl::Impl(TcSoftBody& body, std::shared_ptr<const Net> net, const SolverSettings& solver,
                       const TcSettings& settings)
    : body_(body), net_(std::move(net)), solver_(solver), settings_(settings) {
  if (settings_.blend_steps < 1) throw std::invalid_argument("TcSoftBody: blend_steps must be >= 1");
  if (settings_.start_level < 0) throw std::invalid_argument("TcSoftBody: start_level must be >= 0");
  for (const NetLink& l : net_->links())
    if (l.kind != LinkKind::kStructural)
      throw std::invalid_argument("TcSoftBody: only structural links are supported (no shear or bend links)");
  const LodTree& lod = net_->lod();
  const std::size_t tree_size = lod.size();
  check_solver_settings(solver_);
  if (solver_.compliant_model()) {
    // One material at every level: each link's compliance from the cells around it (tc_compliance.cpp), which the
    // corner shares of masses that follow the cut describe, and no per-level stiffness to mend it.
    if (settings_.masses != Masses::kCut)
      throw std::invalid_argument("TcSoftBody: the compliant material needs masses that follow the cut (Masses::kCut)");
    if (!settings_.level_stiffness.empty())
      throw std::invalid_argument("TcSoftBody: the compliant material takes no per-level stiffness (no calibration)");
    if (!(solver_.compliant.substeps >= 1 && solver_.compliant.stretch_stiffness > 0 && solver_.step_dt > 0))
      throw std::invalid_argument(
          "TcSoftBody: the compliant material needs substeps >= 1, a positive stiffness and dt");
  }
  if (settings_.masses == Masses::kCut) build_corner_shares();
  const std::size_t leaves = lod.leaf_count();

  // Bullet's node array is reserved once for every node of the tree, so no operation ever reallocates it and the
  // raw Node* held by links and DBVT leaves stay valid (docs/design.md, "The node array and raw pointers").
  init_net_nodes(body_, *net_, static_cast<int>(tree_size));
  apply_solver_settings(body_, solver);
  // Made for a world with colliders: soft-rigid contacts on, as Bullet's own default has them, so a cloth dropped on
  // a collider never falls through it for want of a flag (the harness states its own: SceneWorld::attach).
  if (body_.m_worldInfo->m_broadphase != nullptr) body_.m_cfg.collisions = fCollision::SDF_RS;
  for (const double k : settings_.level_stiffness)
    if (!(k > 0 && k <= 1)) throw std::invalid_argument("TcSoftBody: level stiffness must lie in (0, 1]");
  if (!settings_.level_stiffness.empty()) {
    level_materials_.push_back(body_.m_materials[0]);  // level 0: the solver's, as the full-resolution reference's
    for (int level = 1; level < lod.level_count(); ++level) {
      const std::size_t i = std::min(static_cast<std::size_t>(level - 1), settings_.level_stiffness.size() - 1);
      Material* m = body_.appendMaterial();  // a copy of m_materials[0] (flags included)
      m->m_kLST = static_cast<btScalar>(settings_.level_stiffness[i]);
      level_materials_.push_back(m);
    }
  }
  // Room for every link the body can hold at once: the finest cut's links plus what blending operations add. The
  // counter link_reallocations() proves in tests that this never runs out.
  body_.m_links.reserve(static_cast<int>(3 * net_->links().size() + 64));
  append_net_links(body_, *net_);  // the same recipe as the plain baseline: identical body, link for link

  state_.assign(tree_size, CutState::kOff);
  bullet_.assign(tree_size, -1);
  incidence_.assign(tree_size, IncidenceList{});
  record_.assign(tree_size, NodeRecord{});
  for (std::size_t id = 0; id < tree_size; ++id) {
    const btVector3 r = to_bullet(lod.rest(static_cast<TreeId>(id)));
    for (int k = 0; k < 3; ++k) record_[id].rest[k] = r[k];
  }
  tree_of_.reserve(tree_size);  // one entry per simulated node: at most every tree node at once
  tree_of_.resize(leaves);
  for (std::size_t leaf = 0; leaf < leaves; ++leaf) {
    state_[leaf] = CutState::kActive;
    set_bullet_index(static_cast<TreeId>(leaf), static_cast<std::int32_t>(leaf));
    record_[leaf].inv_mass = body_.m_nodes[static_cast<int>(leaf)].m_im;
    tree_of_[leaf] = static_cast<TreeId>(leaf);
    record_[leaf].sim_mass = lod.nodes()[leaf].mass;
    total_mass_ += lod.nodes()[leaf].mass;
  }
  link_meta_.reserve(static_cast<std::size_t>(body_.m_links.capacity()));
  // Each interface constraint holds two links: room for as many as the link array can pair up.
  if (settings_.interfaces == Interfaces::kHanging) {
    interfaces_.reserve(static_cast<std::size_t>(body_.m_links.capacity() / 2));
    prepared_interfaces_.reserve(interfaces_.capacity());
  }
  for (const NetLink& l : net_->links()) {
    const auto index = static_cast<std::int32_t>(link_meta_.size());
    link_meta_.push_back({l.a, l.b, LinkRole::kSteady, -1});
    incidence_[static_cast<std::size_t>(l.a)].add(index);
    incidence_[static_cast<std::size_t>(l.b)].add(index);
  }
  committed_count_ = static_cast<int>(leaves);
  if (solver_.compliant_model())
    for (int li = 0; li < body_.m_links.size(); ++li) write_link_constant(li);

  // Reserved is not yet mapped: the kernel maps a page on its first write. Write the room once now rather than
  // inside operations (a minor fault costs microseconds, more than an operation).
  touch_reserved(body_.m_nodes, zeroed<Node>());
  touch_reserved(body_.m_links, zeroed<Link>());
  touch_reserved(tree_of_, kNoTreeNode);
  touch_reserved(link_meta_, CutLink{});

  if (settings_.start_level > 0) {
    coarsen_to_level(settings_.start_level);
    // Then as a plain body of the coarse cut's size starts: its arrays in order and its node DBVT compact, rather
    // than what the coarsening's swaps and insertions left (the same passes advance_blends() runs on a large body).
    if (settings_.restore_order) restore_order();
    if (settings_.rebuild_dbvt) rebuild_node_dbvt();
  }
}

void TcSoftBody::Impl::simulate_step(btScalar dt) { step_body(body_, dt); }

void TcSoftBody::Impl::move_pins(const btVector3& offset, btScalar dt) {
  for (int i = 0; i < body_.m_nodes.size(); ++i) {
    Node& n = body_.m_nodes[i];
    if (n.m_im != 0) continue;  // only pinned nodes have zero inverse mass (inverse_mass())
    n.m_v = pin_velocity(record(tree_of_[static_cast<std::size_t>(i)]).rest_position(), offset, n.m_x, dt);
  }
  pin_offset_ = offset;
}

int TcSoftBody::Impl::add_node(TreeId id, const btVector3& x, const btVector3& v, TreeId beside) {
  const bool pinned = tree().node(id).pinned();
  // What appendNode does, but with the DBVT leaf placed beside the related node's leaf in O(1) instead of a
  // descent from the root. Capacity was reserved for the whole tree, so the array never reallocates.
  // Zeroed in place (Bullet's ZeroInitialize) rather than built on the stack and copied: 256 bytes written once.
  Node& added = body_.m_nodes.expandNonInitializing();
  const int index = body_.m_nodes.size() - 1;
  std::memset(static_cast<void*>(&added), 0, sizeof(Node));
  added.m_x = x;
  added.m_q = x;
  added.m_v = pinned ? btVector3(0, 0, 0) : v;
  NodeRecord& r = record(id);
  r.inv_mass = added.m_im = inverse_mass(id, r.sim_mass);
  added.m_material = body_.m_materials[0];
  // Every added node arrives in an operation (TcSettings::arrivals_collide); settle_in_cut() lets it collide.
  added.m_battach = settings_.arrivals_collide ? 0 : 1;
  btDbvtNode* beside_leaf = body_.m_nodes[record(beside).bullet].m_leaf;
  added.m_leaf = insert_leaf_beside(body_.m_ndbvt, dbvt_nodes_, beside_leaf,
                                    btDbvtVolume::FromCR(x, body_.getCollisionShape()->getMargin()), &added,
                                    &work_.dbvt_ancestors);
  tree_of_.push_back(id);
  set_bullet_index(id, index);
  faces_stale_ = true;
  interfaces_prepared_ = false;
  ++displaced_;             // appended at the end, away from its neighbours
  work_.nodes += 2;         // the appended node, and the node beside whose leaf it goes
  work_.tree_records += 2;  // id's and beside's
  ++work_.dbvt_leaves;
  return index;
}

void TcSoftBody::Impl::remove_node(TreeId id) {
  const int k = record(id).bullet;
  if (incidence_[static_cast<std::size_t>(id)].size() != 0)
    throw std::logic_error("TcSoftBody::remove_node: node still has links");
  remove_leaf_lazily(body_.m_ndbvt, dbvt_nodes_, body_.m_nodes[k].m_leaf);
  ++work_.nodes;
  ++work_.tree_records;
  ++work_.dbvt_leaves;
  const int last = body_.m_nodes.size() - 1;
  if (k != last) {
    ++work_.relocation_nodes;  // the last node, copied into the hole: its leaf, Bullet index and tree entry
    ++displaced_;
    // Swap-with-last: the moved node's leaf and incident links are re-pointed, O(degree).
    Node* from = &body_.m_nodes[last];
    body_.m_nodes[k] = body_.m_nodes[last];
    Node* to = &body_.m_nodes[k];
    to->m_leaf->data = to;
    const TreeId moved = tree_of_[static_cast<std::size_t>(last)];
    for (std::int32_t li : incidence_[static_cast<std::size_t>(moved)]) {
      ++work_.relocation_links;
      Link& l = body_.m_links[li];
      if (l.m_n[0] == from) l.m_n[0] = to;
      if (l.m_n[1] == from) l.m_n[1] = to;
    }
    tree_of_[static_cast<std::size_t>(k)] = moved;
    set_bullet_index(moved, k);
    follow_anchors(from, to);
  }
  body_.m_nodes.pop_back();
  tree_of_.pop_back();
  set_bullet_index(id, -1);
  faces_stale_ = true;
  interfaces_prepared_ = false;
}

void TcSoftBody::Impl::follow_anchors(const Node* from, Node* to) {
  for (int a = 0; a < body_.m_anchors.size(); ++a)
    if (body_.m_anchors[a].m_node == from) body_.m_anchors[a].m_node = to;
}

void TcSoftBody::Impl::hand_over_anchors(TreeId from, TreeId to) {
  if (body_.m_anchors.size() == 0) return;
  const int f = record(from).bullet, t = record(to).bullet;
  if (f < 0 || t < 0) return;
  bool moved = false;
  for (int a = 0; a < body_.m_anchors.size(); ++a) {
    if (body_.m_anchors[a].m_node != &body_.m_nodes[f]) continue;
    body_.m_anchors[a].m_node = &body_.m_nodes[t];
    moved = true;
  }
  if (moved) body_.m_nodes[t].m_battach = 1;  // as appendAnchor marks the node it anchors
}

void TcSoftBody::Impl::set_bullet_index(TreeId id, std::int32_t index) {
  bullet_[static_cast<std::size_t>(id)] = record(id).bullet = index;
}

btScalar TcSoftBody::Impl::rest_length(TreeId a, TreeId b) const {
  // The same float expression Bullet's resetLinkRestLengths evaluates at rest, so finest-level links match it bit
  // for bit.
  return (record(a).rest_position() - record(b).rest_position()).length();
}

int TcSoftBody::Impl::add_link(TreeId a, TreeId b, LinkRole role, std::int32_t op) {
  if (body_.m_links.size() == body_.m_links.capacity()) ++link_reallocations_;
  Link& l = body_.m_links.expandNonInitializing();  // zeroed in place, as add_node does
  const int index = body_.m_links.size() - 1;
  std::memset(static_cast<void*>(&l), 0, sizeof(Link));
  // Uncalibrated, every link uses the body's one material without reading the tree (bit for bit as before).
  l.m_material = calibrated() ? link_material(a, b) : body_.m_materials[0];
  l.m_n[0] = &body_.m_nodes[record(a).bullet];
  l.m_n[1] = &body_.m_nodes[record(b).bullet];
  l.m_rl = rest_length(a, b);
  l.m_c1 = l.m_rl * l.m_rl;
  link_meta_.push_back({a, b, role, op});
  if (vertex_edges()) l.m_material = edge_material(index);
  incidence_[static_cast<std::size_t>(a)].add(index);
  incidence_[static_cast<std::size_t>(b)].add(index);
  write_link_constant(index);
  if (settings_.interfaces == Interfaces::kHanging) pair_into_interface(index);
  interfaces_prepared_ = false;
  ++displaced_;
  ++work_.links;
  work_.tree_records += 2;  // both endpoints: records read, incidence lists written
  return index;
}

void TcSoftBody::Impl::remove_link(int link) {
  if (link_meta_[static_cast<std::size_t>(link)].interface >= 0) dissolve_interface(link);
  interfaces_prepared_ = false;
  const CutLink meta = link_meta_[static_cast<std::size_t>(link)];
  incidence_[static_cast<std::size_t>(meta.a)].remove(link);
  incidence_[static_cast<std::size_t>(meta.b)].remove(link);
  ++work_.links;
  work_.tree_records += 2;
  const int last = body_.m_links.size() - 1;
  if (link != last) {
    ++work_.relocation_links;  // the last link, copied into the hole; its endpoints' incidence entries re-pointed
    ++displaced_;
    // Swap-with-last: Bullet keeps no pointer to links, only our incidence lists name the moved one.
    body_.m_links[link] = body_.m_links[last];
    link_meta_[static_cast<std::size_t>(link)] = link_meta_[static_cast<std::size_t>(last)];
    const CutLink& moved = link_meta_[static_cast<std::size_t>(link)];
    incidence_[static_cast<std::size_t>(moved.a)].replace(last, link);
    incidence_[static_cast<std::size_t>(moved.b)].replace(last, link);
    if (moved.interface >= 0)
      for (std::int32_t& handle : interfaces_[static_cast<std::size_t>(moved.interface)].links)
        if (handle == last) handle = link;
  }
  body_.m_links.pop_back();
  link_meta_.pop_back();
}

void TcSoftBody::Impl::set_simulated_mass(TreeId id, double mass) {
  ++work_.nodes;
  ++work_.tree_records;
  NodeRecord& r = record(id);
  r.sim_mass = mass;
  r.inv_mass = body_.m_nodes[r.bullet].m_im = inverse_mass(id, mass);
  interfaces_prepared_ = false;
}

btScalar TcSoftBody::Impl::inverse_mass(TreeId id, double mass) const {
  return tree().node(id).pinned() ? btScalar(0) : static_cast<btScalar>(1.0 / mass);
}

btSoftBody::Material* TcSoftBody::Impl::link_material(TreeId a, TreeId b) const {
  if (!calibrated()) return body_.m_materials[0];
  const int level = std::max(tree().node(a).level, tree().node(b).level);
  return level_materials_[static_cast<std::size_t>(level)];
}

double TcSoftBody::Impl::op_progress(const Op& op) const {
  return static_cast<double>(op.step + 1) / (settings_.blend_steps + 1);
}

double TcSoftBody::Impl::blend_alpha(const CutLink& meta) const {
  if (meta.role != LinkRole::kFadeIn && meta.role != LinkRole::kFadeOut) return 1.0;
  const double arriving = op_progress(ops_[static_cast<std::size_t>(meta.op)]);
  return meta.role == LinkRole::kFadeIn ? arriving : 1.0 - arriving;
}

void TcSoftBody::Impl::refresh_link_constant(int link) {
  ++work_.links;
  work_.tree_records += 2;  // both endpoints' records (inverse masses)
  write_link_constant(link);
}

void TcSoftBody::Impl::write_link_constant(int link) {
  Link& l = body_.m_links[link];
  const CutLink& meta = link_meta_[static_cast<std::size_t>(link)];
  // Bullet's updateLinkConstants expression, (m_n[0]->m_im + m_n[1]->m_im) / m_material->m_kLST, read from where it
  // costs fewest cache lines: the inverse masses from the records (equal to Bullet's; not the endpoints' Bullet
  // nodes), the stiffness from the body's one material, which every link uses (validate() checks both), so that
  // only the line holding m_c0 is touched, not the link's first line too (a 72-byte link usually spans two). A
  // blend divides it by alpha, which scales the solver's correction by alpha without touching the rest length
  // (docs/design.md, "Blending through m_c0").
  // Calibrated, each link's own material (its level's stiffness): a fading link fades from its level's constant.
  if (meta.interface >= 0 && !kept_handle(link)) {  // a handle of an interface constraint: Bullet's solver skips it
    l.m_c0 = 0;
    return;
  }
  if (solver_.compliant_model()) {
    l.m_c0 =
        compliant_constant(record(meta.a).inv_mass + record(meta.b).inv_mass, link_stiffness(link), blend_alpha(meta));
    return;
  }
  const btScalar stiffness = calibrated() ? l.m_material->m_kLST : body_.m_materials[0]->m_kLST;
  l.m_c0 = (record(meta.a).inv_mass + record(meta.b).inv_mass) / stiffness;
  const double alpha = blend_alpha(meta);
  if (alpha != 1.0) l.m_c0 = static_cast<btScalar>(l.m_c0 / alpha);
}

void TcSoftBody::Impl::refresh_incident_constants(TreeId id) {
  for (std::int32_t li : incidence_[static_cast<std::size_t>(id)]) refresh_link_constant(li);
}

Eigen::Vector3d TcSoftBody::Impl::linear_momentum() const {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int i = 0; i < body_.m_nodes.size(); ++i) {
    const TreeId id = tree_of_[static_cast<std::size_t>(i)];
    if (tree().node(id).pinned()) continue;
    p += record(id).sim_mass * to_eigen(body_.m_nodes[i].m_v);
  }
  return p;
}

double TcSoftBody::Impl::total_mass() const {
  double sum = 0;
  for (TreeId id : tree_of_) sum += record(id).sim_mass;
  return sum;
}

}  // namespace tcsb
