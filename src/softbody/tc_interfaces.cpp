// TcSoftBody: hanging interfaces — the constraint that replaces a fan where a coarse block meets finer cloth, kept
// by the operations in O(degree), and the constraint solve that projects it in every position iteration.
//
// Why (docs/design.md, "Interfaces between levels"): a coarse node linked to the two finer nodes facing its side pulls
// them towards each other under tension, which the fine cloth's straight links do not; no stiffness mends it. One
// distance constraint from the coarse node to the fine nodes' midpoint carries the same load without the sideways
// pull, as a hanging node of an adaptive mesh is held to the point its coarse neighbours give it.
#include <BulletSoftBody/btSoftBodyInternals.h>

#include "softbody/fan_rule.h"
#include "softbody/tc_softbody.h"

namespace tcsb {

void TcSoftBody::pair_into_interface(int link) {
  const CutLink& added = link_meta_[static_cast<std::size_t>(link)];
  if (added.role == LinkRole::kTether) return;  // a tether joins a node to its own children: no interface
  const LodNode& a = tree().node(added.a);
  const LodNode& b = tree().node(added.b);
  if (a.level == b.level) return;
  const TreeId coarse = a.level > b.level ? added.a : added.b;
  const TreeId fine = added.other(coarse);
  const LodNode& fine_node = a.level > b.level ? b : a;
  // The other link of the fan: from the same coarse node to the fine node's sibling (fan_rule.h).
  for (const std::int32_t li : incidence_[static_cast<std::size_t>(coarse)]) {
    if (li == link) continue;
    const CutLink& m = link_meta_[static_cast<std::size_t>(li)];
    if (m.interface >= 0 || m.role != added.role || m.op != added.op) continue;
    ++work_.tree_records;  // the candidate's LOD node
    if (!forms_fan(tree(), coarse, added, m)) continue;
    const TreeId sibling = m.other(coarse);
    const btVector3 midpoint = (record(fine).rest_position() + record(sibling).rest_position()) * btScalar(0.5);
    const auto index = static_cast<std::int32_t>(interfaces_.size());
    interfaces_.push_back({.coarse = coarse,
                           .fine = {sibling, fine},
                           .links = {li, link},
                           .rest = (midpoint - record(coarse).rest_position()).length(),
                           .stiffness = interface_stiffness(fine_node.level)});
    link_meta_[static_cast<std::size_t>(li)].interface = index;
    link_meta_[static_cast<std::size_t>(link)].interface = index;
    write_link_constant(li);
    write_link_constant(link);
    return;
  }
}

btScalar TcSoftBody::interface_stiffness(int fine_level) const {
  if (!calibrated()) return m_materials[0]->m_kLST;
  // The constraint spans cloth of both levels (from the coarse node to its block's edge, then into the finer
  // block), so it takes the mean of their calibrated stiffnesses. Measured on fixed cuts of the converged suite's
  // nets against the coarser level's stiffness alone, the finer's, their series combinations and fixed values
  // (docs/investigations/hanging-interfaces.md): the mean is within the broad best range on every cut tried.
  const auto level = static_cast<std::size_t>(fine_level);
  return (level_materials_[level]->m_kLST + level_materials_[level + 1]->m_kLST) / 2;
}

void TcSoftBody::dissolve_interface(int link) {
  const auto index = static_cast<std::size_t>(link_meta_[static_cast<std::size_t>(link)].interface);
  const InterfaceConstraint gone = interfaces_[index];
  for (const std::int32_t handle : gone.links) link_meta_[static_cast<std::size_t>(handle)].interface = -1;
  const std::int32_t partner = gone.links[0] == link ? gone.links[1] : gone.links[0];
  write_link_constant(partner);  // a plain link again, until its own removal (both go in the same operation)
  if (index + 1 != interfaces_.size()) {
    interfaces_[index] = interfaces_.back();
    for (const std::int32_t handle : interfaces_[index].links)
      link_meta_[static_cast<std::size_t>(handle)].interface = static_cast<std::int32_t>(index);
  }
  interfaces_.pop_back();
}

void TcSoftBody::prepare_interfaces() {
  prepared_interfaces_.resize(interfaces_.size());
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    const InterfaceConstraint& c = interfaces_[i];
    PreparedInterface& p = prepared_interfaces_[i];
    p.coarse = &m_nodes[record(c.coarse).bullet];
    p.fine[0] = &m_nodes[record(c.fine[0]).bullet];
    p.fine[1] = &m_nodes[record(c.fine[1]).bullet];
    // Position-based dynamics for C(x) = |(x_f0 + x_f1)/2 - x_c| - rest: gradients -n for the coarse node and n/2
    // for each fine one, so the generalised inverse mass is w_c + (w_f0 + w_f1)/4. As for a link, the blend weight
    // divides the constant (docs/design.md, "Blending through m_c0").
    const btScalar w = p.coarse->m_im + btScalar(0.25) * (p.fine[0]->m_im + p.fine[1]->m_im);
    const double alpha = blend_alpha(link_meta_[static_cast<std::size_t>(c.links[0])]);
    p.c0 = w > 0 ? static_cast<btScalar>(w / c.stiffness / alpha) : btScalar(0);
    p.c1 = c.rest * c.rest;
  }
}

void TcSoftBody::project_interfaces() {
  // Bullet's link projection (btSoftBody::PSolve_Links: the square-root-free correction k) with the fine end at
  // the midpoint, the correction shared half and half.
  for (const PreparedInterface& p : prepared_interfaces_) {
    if (p.c0 <= 0) continue;
    Node& c = *p.coarse;
    Node& f0 = *p.fine[0];
    Node& f1 = *p.fine[1];
    const btVector3 del = (f0.m_x + f1.m_x) * btScalar(0.5) - c.m_x;
    const btScalar len = del.length2();
    if (p.c1 + len <= SIMD_EPSILON) continue;
    const btScalar k = (p.c1 - len) / (p.c0 * (p.c1 + len));
    c.m_x -= del * (k * c.m_im);
    f0.m_x += del * (k * btScalar(0.5) * f0.m_im);
    f1.m_x += del * (k * btScalar(0.5) * f1.m_im);
  }
}

void TcSoftBody::solve_constraints() {
  if (interfaces_.empty()) {
    btSoftBody::solveConstraints();
    return;
  }
  // Bullet's btSoftBody::solveConstraints, step for step, with the interfaces projected after the configured position
  // solvers of every iteration; the interface handles (m_c0 = 0) take no part in the velocity solve. The cluster
  // steps stay although TC-SB has no clusters: they cost what they cost a plain body (two node-sized arrays
  // allocated and zeroed), so the comparison stays fair.
  applyClusters(false);
  for (int i = 0; i < m_links.size(); ++i) {
    Link& l = m_links[i];
    l.m_c3 = l.m_n[1]->m_q - l.m_n[0]->m_q;
    l.m_c2 = l.m_c0 > 0 ? 1 / (l.m_c3.length2() * l.m_c0) : btScalar(0);
  }
  for (int i = 0; i < m_anchors.size(); ++i) {
    Anchor& a = m_anchors[i];
    const btVector3 ra = a.m_body->getWorldTransform().getBasis() * a.m_local;
    a.m_c0 = ImpulseMatrix(m_sst.sdt, a.m_node->m_im, a.m_body->getInvMass(), a.m_body->getInvInertiaTensorWorld(), ra);
    a.m_c1 = ra;
    a.m_c2 = m_sst.sdt * a.m_node->m_im;
    a.m_body->activate();
  }
  prepare_interfaces();
  if (m_cfg.viterations > 0) {
    for (int iteration = 0; iteration < m_cfg.viterations; ++iteration)
      for (int s = 0; s < m_cfg.m_vsequence.size(); ++s) getSolver(m_cfg.m_vsequence[s])(this, 1);
    for (int i = 0; i < m_nodes.size(); ++i) m_nodes[i].m_x = m_nodes[i].m_q + m_nodes[i].m_v * m_sst.sdt;
  }
  if (m_cfg.piterations > 0) {
    for (int iteration = 0; iteration < m_cfg.piterations; ++iteration) {
      const btScalar ti = iteration / static_cast<btScalar>(m_cfg.piterations);
      for (int s = 0; s < m_cfg.m_psequence.size(); ++s) getSolver(m_cfg.m_psequence[s])(this, 1, ti);
      project_interfaces();
    }
    const btScalar vc = m_sst.isdt * (1 - m_cfg.kDP);
    for (int i = 0; i < m_nodes.size(); ++i) {
      Node& n = m_nodes[i];
      n.m_v = (n.m_x - n.m_q) * vc;
      n.m_f = btVector3(0, 0, 0);
    }
  }
  if (m_cfg.diterations > 0) {
    const btScalar vcf = m_cfg.kVCF * m_sst.isdt;
    for (int i = 0; i < m_nodes.size(); ++i) m_nodes[i].m_q = m_nodes[i].m_x;
    for (int iteration = 0; iteration < m_cfg.diterations; ++iteration) {
      for (int s = 0; s < m_cfg.m_dsequence.size(); ++s) getSolver(m_cfg.m_dsequence[s])(this, 1, 0);
      project_interfaces();
    }
    for (int i = 0; i < m_nodes.size(); ++i) m_nodes[i].m_v += (m_nodes[i].m_x - m_nodes[i].m_q) * vcf;
  }
  dampClusters();
  applyClusters(true);
}

}  // namespace tcsb
