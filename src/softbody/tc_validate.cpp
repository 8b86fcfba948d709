// TcSoftBody::validate(): every invariant of the TreeCut soft body, checked in one place (tests and debug runs).
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <utility>
#include <vector>

#include "net/cut_adjacency.h"
#include "softbody/dbvt_local.h"
#include "softbody/fan_rule.h"
#include "softbody/tc_softbody_impl.h"
#include "softbody/tc_softbody_solver.h"

namespace tcsb {

namespace {
bool finite(const btVector3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }
}  // namespace

Validation TcSoftBody::Impl::validate() const {
  Validation out;
  const ProblemSink fail = [&](const std::string& what) {
    if (out.problems.size() < 50) out.problems.push_back(what);
  };
  // In this order: a broken setup explains much of what follows, and an anchor that lost its node is named as such
  // before the node it left behind is reported.
  validate_world_setup(fail);
  validate_anchors(fail);
  validate_node_mapping(fail);
  validate_masses(fail);
  validate_link_constants(fail);
  validate_interfaces(fail);
  validate_no_unpaired_fans(fail);
  validate_faces(fail);
  validate_incidence(fail);
  validate_cut_partition(fail);
  validate_committed_links(fail);
  validate_operations(fail);
  return out;
}

void TcSoftBody::Impl::validate_world_setup(const ProblemSink& fail) const {
  if (body_.m_bUpdateRtCst) fail("m_bUpdateRtCst is set: the next step would reset every rest length");
  // Bullet's default solver calls btSoftBody::solveConstraints, which skips the interface constraints' handles
  // (m_c0 = 0) and projects nothing in their place: the levels would come apart. A world hands its solver to every
  // body it adds (btSoftRigidDynamicsWorld::addSoftBody, setSoftBodySolver); a body stepped solo has none.
  // The compliant material likewise: Bullet's default solver would take one step of Bullet's iterations with the
  // compliant constants, another cloth.
  if (body_.getSoftBodySolver() != nullptr &&
      dynamic_cast<const TcSoftBodySolver*>(body_.getSoftBodySolver()) == nullptr) {
    if (settings_.interfaces == Interfaces::kHanging)
      fail("hanging interfaces in a world whose soft-body solver is not a tcsb::TcSoftBodySolver: build the world "
           "with one (tc_softbody_solver.h)");
    if (solver_.compliant_model())
      fail("the compliant material in a world whose soft-body solver is not a tcsb::TcSoftBodySolver: build the "
           "world with one (tc_softbody_solver.h)");
  }
  if (body_.m_nodes.capacity() < static_cast<int>(tree().size())) fail("node capacity below the tree size");
  // In a collision world (the world gave the body a broadphase proxy) the body's world info must be that world's:
  // Bullet's step updates the body's box in m_worldInfo->m_broadphase, and an info of the body's own has none.
  if (body_.getBroadphaseHandle() != nullptr &&
      (body_.m_worldInfo == nullptr || body_.m_worldInfo->m_broadphase == nullptr))
    fail("in a collision world but built with a btSoftBodyWorldInfo that has no broadphase (not the world's "
         "getWorldInfo()): the world's next step would crash in btSoftBody::updateBounds");
}

void TcSoftBody::Impl::validate_anchors(const ProblemSink& fail) const {
  // Anchors (appendAnchor: a node attached to a rigid body) hold a Node*, which the body re-points whenever it moves
  // the node (follow_anchors, restore_order, hand_over_anchors).
  for (int a = 0; a < body_.m_anchors.size(); ++a) {
    const std::string name = "anchor " + std::to_string(a);
    const std::ptrdiff_t i = body_.m_nodes.size() > 0 ? body_.m_anchors[a].m_node - &body_.m_nodes[0] : -1;
    if (i < 0 || i >= body_.m_nodes.size()) {
      fail(name + ": points at no simulated node (its Node* is past the live nodes or not this body's): the cloth is "
                  "no longer attached to its rigid body");
      continue;
    }
    const TreeId id = tree_of_[static_cast<std::size_t>(i)];
    if (body_.m_anchors[a].m_body == nullptr) fail(name + ": has no rigid body");
    const Node& node = body_.m_nodes[static_cast<int>(i)];
    if (node.m_battach == 0)
      fail(name + ": its node (Bullet " + std::to_string(i) + ", tree " + std::to_string(id) +
           ") is not marked attached (m_battach, which appendAnchor sets): a stale Node* that landed on another node, "
           "or an anchor appended without appendAnchor");
    if (node.m_im == 0 && body_.m_anchors[a].m_body != nullptr && body_.m_anchors[a].m_body->getInvMass() == 0)
      fail(name + ": holds a pinned node (tree " + std::to_string(id) +
           ") to a static body: Bullet's anchor solve divides by their zero inverse masses");
  }
}

void TcSoftBody::Impl::validate_node_mapping(const ProblemSink& fail) const {
  // Every Bullet node simulates one tree node of the cut and maps back to it, with its own DBVT leaf.
  const std::size_t tree_size = tree().size();
  if (static_cast<int>(tree_of_.size()) != body_.m_nodes.size()) fail("tree_of_ size differs from Bullet's node count");
  if (const char* dbvt = check_dbvt(body_.m_ndbvt); *dbvt != 0) fail(std::string("node DBVT: ") + dbvt);
  if (body_.m_ndbvt.m_leaves != body_.m_nodes.size())
    fail("DBVT has " + std::to_string(body_.m_ndbvt.m_leaves) + " leaves for " + std::to_string(body_.m_nodes.size()) +
         " nodes");
  for (int i = 0; i < body_.m_nodes.size() && i < static_cast<int>(tree_of_.size()); ++i) {
    const TreeId id = tree_of_[static_cast<std::size_t>(i)];
    const Node& n = body_.m_nodes[i];
    const std::string name = simulated_node_name(i);
    if (id < 0 || static_cast<std::size_t>(id) >= tree_size) {
      fail(name + ": tree id out of range");
      continue;
    }
    if (record(id).bullet != i) fail(name + ": Bullet index does not map back");
    if (state(id) == CutState::kOff) fail(name + ": simulated but off the cut");
    if (n.m_leaf == nullptr || n.m_leaf->data != &n) fail(name + ": DBVT leaf missing or pointing elsewhere");
    // Out of contact exactly while it arrives, and only under the paper's rule (TcSettings::arrivals_collide).
    // (Bullet's appendAnchor sets the same flag on an anchored node.)
    if ((n.m_battach != 0) != (anchored(id) || (!settings_.arrivals_collide && state(id) == CutState::kArriving)))
      fail(name + (n.m_battach != 0 ? ": out of collisions (m_battach) but no anchor holds it and it is not an "
                                      "arriving node of the paper's rule"
                                    : ": arriving under the paper's rule but taking part in collisions"));
    if (!finite(n.m_x) || !finite(n.m_v)) fail(name + ": NaN or Inf position/velocity");
  }
  for (std::size_t id = 0; id < tree_size; ++id) {
    if ((bullet_[id] >= 0) != (state_[id] != CutState::kOff))
      fail("tree " + std::to_string(id) + ": state and simulation disagree");
    if (bullet_[id] != record_[id].bullet) fail("tree " + std::to_string(id) + ": the two Bullet indices disagree");
  }
}

void TcSoftBody::Impl::validate_masses(const ProblemSink& fail) const {
  // Each simulated node carries what its block (or the cut) gives it, Bullet's inverse mass is its inverse, pinned
  // nodes sit on their pins, and the total is the net's.
  const LodTree& lod = tree();
  double mass = 0;
  for (int i = 0; i < body_.m_nodes.size() && i < static_cast<int>(tree_of_.size()); ++i) {
    const TreeId id = tree_of_[static_cast<std::size_t>(i)];
    if (id < 0 || static_cast<std::size_t>(id) >= lod.size()) continue;  // validate_node_mapping names it
    const Node& n = body_.m_nodes[i];
    const std::string name = simulated_node_name(i);
    const LodNode& t = lod.node(id);
    const double m = record(id).sim_mass;
    mass += m;
    if (t.pinned()) {
      if (n.m_im != 0) fail(name + ": pinned but has finite mass");
      if ((n.m_x - pin_position(id)).length() > 1e-6 * net_->extent())
        fail(name + ": pinned node moved off its pin (rest + pin offset)");
    } else if (!(m > 0) || std::abs(n.m_im * m - 1.0) > 1e-5) {
      fail(name + ": inverse mass does not match its carried mass");
    }
    if (record(id).inv_mass != n.m_im) fail(name + ": the record's inverse mass differs from Bullet's");
    if (cut_masses()) {
      if (std::abs(m - target_mass(id)) > 1e-9 * t.mass) fail(name + ": carried mass is not what the cut gives it");
    } else {
      const double expected = (state(id) == CutState::kActive) ? t.mass : 0.5 * t.mass;
      if (std::abs(m - expected) > 1e-9 * t.mass) fail(name + ": carried mass is not its block's (or half of it)");
    }
  }
  if (std::abs(mass - total_mass_) > 1e-6 * total_mass_)
    fail("total mass " + std::to_string(mass) + " differs from " + std::to_string(total_mass_));
}

std::string TcSoftBody::Impl::simulated_node_name(int index) const {
  return "node " + std::to_string(index) + " (tree " + std::to_string(tree_of_[static_cast<std::size_t>(index)]) + ")";
}

void TcSoftBody::Impl::validate_link_constants(const ProblemSink& fail) const {
  // Every Bullet link joins the nodes its CutLink names, at their rest distance, with its level's material and the
  // constant its endpoints' masses and its blend weight give.
  if (static_cast<int>(link_meta_.size()) != body_.m_links.size())
    fail("link_meta_ size differs from Bullet's link count");
  for (int li = 0; li < body_.m_links.size() && li < static_cast<int>(link_meta_.size()); ++li) {
    const Link& l = body_.m_links[li];
    const CutLink& meta = link_meta_[static_cast<std::size_t>(li)];
    const std::string name = "link " + std::to_string(li);
    const int ba = record(meta.a).bullet, bb = record(meta.b).bullet;
    if (ba < 0 || bb < 0) {
      fail(name + ": endpoint not simulated");
      continue;
    }
    if (l.m_n[0] != &body_.m_nodes[ba] || l.m_n[1] != &body_.m_nodes[bb])
      fail(name + ": node pointers disagree with metadata");
    if (!incidence_[static_cast<std::size_t>(meta.a)].contains(li) ||
        !incidence_[static_cast<std::size_t>(meta.b)].contains(li))
      fail(name + ": missing from an endpoint's incidence list");
    if (l.m_rl != rest_length(meta.a, meta.b) || l.m_c1 != l.m_rl * l.m_rl) fail(name + ": rest length changed");
    const bool blended = meta.role == LinkRole::kFadeIn || meta.role == LinkRole::kFadeOut;
    if ((meta.role == LinkRole::kSteady) != (meta.op < 0)) fail(name + ": steady links own no operation");
    if (l.m_material != edge_material(li)) fail(name + ": not the material of its level");
    if (meta.interface >= 0 && !kept_handle(li)) {
      if (l.m_c0 != 0) fail(name + ": a handle of an interface constraint, but Bullet's link solver would solve it");
      continue;
    }
    btScalar c0 = 0;
    if (solver_.compliant_model()) {
      c0 = compliant_constant(l.m_n[0]->m_im + l.m_n[1]->m_im, link_stiffness(li), blended ? blend_alpha(meta) : 1.0);
    } else {
      c0 = (l.m_n[0]->m_im + l.m_n[1]->m_im) / l.m_material->m_kLST;
      if (blended) c0 = static_cast<btScalar>(c0 / blend_alpha(meta));
    }
    if (std::abs(l.m_c0 - c0) > 1e-5f * std::abs(c0)) fail(name + ": m_c0 does not match masses and blend");
  }
}

void TcSoftBody::Impl::validate_incidence(const ProblemSink& fail) const {
  // The incidence lists hold each link twice, once at each endpoint, and nothing else.
  const std::size_t tree_size = tree().size();
  std::size_t incidence_total = 0;
  for (std::size_t id = 0; id < tree_size; ++id) incidence_total += static_cast<std::size_t>(incidence_[id].size());
  if (incidence_total != 2 * static_cast<std::size_t>(body_.m_links.size()))
    fail("incidence lists hold " + std::to_string(incidence_total) + " entries for " +
         std::to_string(body_.m_links.size()) + " links");
  for (std::size_t id = 0; id < tree_size; ++id)
    for (std::int32_t li : incidence_[id])
      if (li < 0 || li >= static_cast<std::int32_t>(link_meta_.size()) ||
          (link_meta_[static_cast<std::size_t>(li)].a != static_cast<TreeId>(id) &&
           link_meta_[static_cast<std::size_t>(li)].b != static_cast<TreeId>(id)))
        fail("tree " + std::to_string(id) + ": incidence entry names a link not touching it");
}

void TcSoftBody::Impl::validate_cut_partition(const ProblemSink& fail) const {
  // The committed cut (active + arriving) and the old cut (active + leaving) each cover every leaf once.
  const LodTree& lod = tree();
  for (std::size_t leaf = 0; leaf < lod.leaf_count(); ++leaf) {
    int in_new = 0, in_old = 0;
    for (TreeId id = static_cast<TreeId>(leaf); id != kNoTreeNode; id = lod.node(id).parent) {
      const CutState s = state(id);
      in_new += (s == CutState::kActive || s == CutState::kArriving);
      in_old += (s == CutState::kActive || s == CutState::kLeaving);
    }
    if (in_new != 1 || in_old != 1)
      fail("leaf " + std::to_string(leaf) + " covered " + std::to_string(in_new) + "x by the cut and " +
           std::to_string(in_old) + "x by the old cut");
  }
}

void TcSoftBody::Impl::validate_committed_links(const ProblemSink& fail) const {
  // The committed cut is balanced, and every committed node is linked to exactly its committed neighbours.
  const LodTree& lod = tree();
  int committed_nodes = 0;
  for (std::size_t id = 0; id < lod.size(); ++id) {
    const TreeId t = static_cast<TreeId>(id);
    if (!committed(t)) continue;
    ++committed_nodes;
    const int level = lod.node(t).level;
    const bool balanced = for_each_cut_neighbour(
        lod, t, [this](TreeId n) { return committed(n); },
        [&](TreeId n) {
          if (std::abs(lod.node(n).level - level) > 1)
            fail("tree " + std::to_string(t) + ": neighbour two levels apart");
          bool linked = false;
          for (std::int32_t li : incidence_[id]) {
            const CutLink& m = link_meta_[static_cast<std::size_t>(li)];
            linked |= (m.a == n || m.b == n) && m.role != LinkRole::kFadeOut && m.role != LinkRole::kTether &&
                      m.role != LinkRole::kDoomed;
          }
          if (!linked) fail("tree " + std::to_string(t) + ": no link to committed neighbour " + std::to_string(n));
        });
    if (!balanced) fail("tree " + std::to_string(t) + ": the committed cut is not balanced around it");
  }
  if (committed_nodes != committed_count_) fail("committed node count is stale");
}

void TcSoftBody::Impl::validate_operations(const ProblemSink& fail) const {
  // Each operation in flight owns its subjects and is inside its blend; no operation grew the link array.
  for (std::size_t slot = 0; slot < inflight_.size(); ++slot) {
    const Op& op = ops_[static_cast<std::size_t>(inflight_[slot])];
    if (op.slot != static_cast<std::int32_t>(slot)) fail("operation slot stale");
    if (record(op.parent).op != inflight_[slot]) fail("operation does not own its parent");
    if (op.step < 0 || op.step >= settings_.blend_steps) fail("operation step out of range");
  }
  if (link_reallocations_ != 0) fail("the link array was reallocated during an operation");
}

void TcSoftBody::Impl::validate_interfaces(const ProblemSink& fail) const {
  const LodTree& lod = tree();
  if (settings_.interfaces == Interfaces::kLinks && !interfaces_.empty()) fail("interface constraints with fans");
  // Each constraint: its two handles name it, join its coarse node to its two fine nodes (siblings one level finer),
  // share a role and an operation, and its rest distance is the rest midpoint's. Each (coarse node, neighbouring
  // block) pair has at most one constraint, so every interface node is constrained once per coarse side it faces.
  std::vector<std::pair<TreeId, TreeId>> sides;
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    const InterfaceConstraint& c = interfaces_[i];
    const std::string name = "interface " + std::to_string(i);
    bool handles_ok = true;
    for (int k = 0; k < 2; ++k) {
      const std::int32_t li = c.links[static_cast<std::size_t>(k)];
      if (li < 0 || li >= static_cast<std::int32_t>(link_meta_.size())) {
        handles_ok = false;
        continue;
      }
      const CutLink& m = link_meta_[static_cast<std::size_t>(li)];
      const TreeId fine = c.fine[static_cast<std::size_t>(k)];
      handles_ok &= m.interface == static_cast<std::int32_t>(i) &&
                    ((m.a == c.coarse && m.b == fine) || (m.b == c.coarse && m.a == fine));
    }
    if (!handles_ok) {
      fail(name + ": its handles do not name it or do not join its nodes");
      continue;
    }
    const CutLink& m0 = link_meta_[static_cast<std::size_t>(c.links[0])];
    const CutLink& m1 = link_meta_[static_cast<std::size_t>(c.links[1])];
    if (m0.role != m1.role || m0.op != m1.op) fail(name + ": its handles differ in role or operation");
    if (m0.role == LinkRole::kTether) fail(name + ": made of tethers");
    const LodNode& f0 = lod.node(c.fine[0]);
    const LodNode& f1 = lod.node(c.fine[1]);
    if (c.fine[0] == c.fine[1] || f0.parent != f1.parent || f0.level + 1 != lod.node(c.coarse).level)
      fail(name + ": its fine nodes are not two siblings one level finer than its coarse node");
    // Its kind, kept handle, corner and rest distance are what its nodes make of it.
    InterfaceConstraint remade = c;
    remade.kind = InterfaceKind::kMidpoint;
    remade.kept = -1;
    remade.corner_leaf = kNoTreeNode;
    const btVector3 midpoint = (record(c.fine[0]).rest_position() + record(c.fine[1]).rest_position()) * btScalar(0.5);
    remade.rest = (midpoint - record(c.coarse).rest_position()).length();
    remade.stiffness = interface_stiffness(f0.level);
    if (lod.placement() == RestPlacement::kVertex) make_vertex_interface(remade);
    if (c.kind != remade.kind || c.kept != remade.kept || c.corner_leaf != remade.corner_leaf)
      fail(name + ": not the kind its nodes' rest positions make");
    if (c.rest != remade.rest) fail(name + ": rest distance changed");
    if (c.stiffness != remade.stiffness) fail(name + ": not the stiffness of its levels");
    sides.emplace_back(c.coarse, f0.parent);
  }
  std::sort(sides.begin(), sides.end());
  if (std::adjacent_find(sides.begin(), sides.end()) != sides.end())
    fail("two interface constraints for one side of a coarse block");
}

void TcSoftBody::Impl::validate_no_unpaired_fans(const ProblemSink& fail) const {
  if (settings_.interfaces != Interfaces::kHanging) return;
  // No two unpaired links from one coarse node to two siblings one level finer, in one role and operation (tethers
  // aside): with hanging interfaces every fan is one constraint.
  const LodTree& lod = tree();
  for (std::size_t li = 0; li < link_meta_.size(); ++li) {
    const CutLink& m = link_meta_[li];
    if (m.interface >= 0 || m.role == LinkRole::kTether) continue;
    const int la = lod.node(m.a).level, lb = lod.node(m.b).level;
    if (la == lb) continue;
    const TreeId coarse = la > lb ? m.a : m.b;
    for (const std::int32_t other : incidence_[static_cast<std::size_t>(coarse)]) {
      const CutLink& o = link_meta_[static_cast<std::size_t>(other)];
      if (static_cast<std::size_t>(other) != li && o.interface < 0 && forms_fan(lod, coarse, m, o))
        fail("link " + std::to_string(li) + ": a fan left unpaired with link " + std::to_string(other));
    }
  }
}

}  // namespace tcsb
