// TcSoftBody: hanging interfaces — the constraint that replaces a fan where a coarse block meets finer cloth, kept
// by the operations in O(degree), and the constraint solve that projects it in every position iteration.
//
// Why (docs/design.md, "Interfaces between levels"): a coarse node linked to the two finer nodes facing its side pulls
// them towards each other under tension, which the fine cloth's straight links do not; no stiffness mends it. One
// distance constraint from the coarse node to the fine nodes' midpoint carries the same load without the sideways
// pull, as a hanging node of an adaptive mesh is held to the point its coarse neighbours give it.
// On a tree whose blocks rest on their first leaf the same handles carry the vertex form of that constraint
// (InterfaceKind in tc_softbody.h; make_vertex_interface).
#include <BulletSoftBody/btSoftBodyInternals.h>

#include "softbody/compliant_solver.h"
#include "softbody/fan_rule.h"
#include "softbody/tc_softbody_impl.h"

namespace tcsb {

void TcSoftBody::Impl::pair_into_interface(int link) {
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
    if (tree().placement() == RestPlacement::kVertex) make_vertex_interface(interfaces_.back());
    link_meta_[static_cast<std::size_t>(li)].interface = index;
    link_meta_[static_cast<std::size_t>(link)].interface = index;
    body_.m_links[li].m_material = edge_material(li);  // (a kept handle on a -x or -z side: the finer level's)
    body_.m_links[link].m_material = edge_material(link);
    write_link_constant(li);
    write_link_constant(link);
    return;
  }
}

void TcSoftBody::Impl::make_vertex_interface(InterfaceConstraint& c) const {
  const LodNode& block = tree().node(c.coarse);
  const LodNode& f = tree().node(c.fine[0]);
  const btVector3 r = record(c.coarse).rest_position();
  // The side the fine pair faces, and which of the two is in line with the coarse node along it.
  const bool along_z = f.leaf_x0 >= block.leaf_x1 || f.leaf_x1 <= block.leaf_x0;  // on the -x or +x side
  const bool near = along_z ? f.leaf_x1 <= block.leaf_x0 : f.leaf_y1 <= block.leaf_y0;
  for (std::size_t k = 0; k < 2; ++k) {
    const btVector3 rf = record(c.fine[k]).rest_position();
    if (along_z ? rf.z() != r.z() : rf.x() != r.x()) continue;
    c.kept = static_cast<std::int8_t>(k);
    c.kind = near ? InterfaceKind::kVertexNear : InterfaceKind::kVertexFar;
  }
  if (c.kept < 0) return;  // (no fine node in line: the midpoint constraint stays)
  // Both kinds stand for the finer cloth (a fine link to a point of the coarse side, or a fine node on a coarse
  // edge): the finer level's stiffness.
  c.stiffness = level_stiffness(f.level);
  // The far corner the constraint needs: near, the block's corner along the side (+z for a pair on its -x side, +x
  // for one on its -z side), whose node and the coarse node span the side the hanging node's link meets; far, the
  // block's diagonal corner, whose node and the kept fine node span the coarse cell's edge the hanging node lies on.
  const int width = tree().level_width(0), height = tree().level_height(0);
  const LodNode& rest_leaf = tree().node(tree().rest_leaf(c.coarse));
  const int x = near ? (along_z ? rest_leaf.gx : block.leaf_x1) : block.leaf_x1;
  const int z = near ? (along_z ? block.leaf_y1 : rest_leaf.gy) : block.leaf_y1;
  if (x >= width || z >= height) {
    c.kind = InterfaceKind::kVertexFar;  // the side ends at the net's border: nothing to hang from
    return;
  }
  c.corner_leaf = tree().at(0, x, z);
  const btVector3 hanging = record(c.fine[c.kept == 0 ? 1 : 0]).rest_position();
  const btVector3 other = near ? r : record(c.fine[static_cast<std::size_t>(c.kept)]).rest_position();
  c.rest = (hanging - (other + record(c.corner_leaf).rest_position()) * btScalar(0.5)).length();
}

btScalar TcSoftBody::Impl::level_stiffness(int level) const {
  return calibrated() ? level_materials_[static_cast<std::size_t>(level)]->m_kLST : body_.m_materials[0]->m_kLST;
}

btSoftBody::Material* TcSoftBody::Impl::edge_material(int link) const {
  const CutLink& meta = link_meta_[static_cast<std::size_t>(link)];
  if (!vertex_edges() || meta.role == LinkRole::kTether) return link_material(meta.a, meta.b);
  // On a first-leaf tree a link along a row or column is the edge between two cells of the cut: the block its lower
  // end starts (above or to the right of it) and the one holding the leaf just below or to the left. It takes the
  // finer one's stiffness, as the edge a coarse cell shares with finer cloth is, in the reference, that cloth's.
  const LodNode& a = tree().node(tree().rest_leaf(meta.a));
  const LodNode& b = tree().node(tree().rest_leaf(meta.b));
  if (a.gx != b.gx && a.gy != b.gy) return link_material(meta.a, meta.b);  // a slanted handle (never solved)
  const bool along_x = a.gy == b.gy;
  const LodNode& low = (along_x ? a.gx < b.gx : a.gy < b.gy) ? a : b;
  int level = tree().node(holding(low.gx, low.gy, true)).level;
  const int x = along_x ? low.gx : low.gx - 1, z = along_x ? low.gy - 1 : low.gy;
  if (x >= 0 && z >= 0) level = std::min<int>(level, tree().node(holding(x, z, true)).level);
  return level_materials_[static_cast<std::size_t>(level)];
}

btScalar TcSoftBody::Impl::interface_stiffness(int fine_level) const {
  // The constraint spans cloth of both levels (from the coarse node to its block's edge, then into the finer
  // block), so it takes the mean of their calibrated stiffnesses. Measured on fixed cuts of the converged suite's
  // nets against the coarser level's stiffness alone, the finer's, their series combinations and fixed values
  // (docs/investigations/hanging-interfaces.md): the mean is within the broad best range on every cut tried.
  // (Uncalibrated both are the solver's, and so is their mean.)
  return (level_stiffness(fine_level) + level_stiffness(fine_level + 1)) / 2;
}

void TcSoftBody::Impl::dissolve_interface(int link) {
  const auto index = static_cast<std::size_t>(link_meta_[static_cast<std::size_t>(link)].interface);
  const InterfaceConstraint gone = interfaces_[index];
  for (const std::int32_t handle : gone.links) link_meta_[static_cast<std::size_t>(handle)].interface = -1;
  const std::int32_t partner = gone.links[0] == link ? gone.links[1] : gone.links[0];
  body_.m_links[partner].m_material = edge_material(partner);
  write_link_constant(partner);  // a plain link again, until its own removal (both go in the same operation)
  if (index + 1 != interfaces_.size()) {
    interfaces_[index] = interfaces_.back();
    for (const std::int32_t handle : interfaces_[index].links)
      link_meta_[static_cast<std::size_t>(handle)].interface = static_cast<std::int32_t>(index);
  }
  interfaces_.pop_back();
}

void TcSoftBody::Impl::prepare_interfaces() {
  // What it computes follows the nodes' places and masses, the interfaces and the blend weights: on a body that no
  // operation touched since, nor blends, it is what the last step used.
  if (interfaces_prepared_) return;
  prepared_interfaces_.resize(interfaces_.size());
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    const InterfaceConstraint& c = interfaces_[i];
    PreparedInterface& p = prepared_interfaces_[i];
    btScalar rest = c.rest;
    TreeId corner = kNoTreeNode;  // vertex kinds: the node resting at the corner the constraint reaches, if any
    if (c.kind == InterfaceKind::kMidpoint) {
      p.coarse = &body_.m_nodes[record(c.coarse).bullet];
      p.fine[0] = &body_.m_nodes[record(c.fine[0]).bullet];
      p.fine[1] = &body_.m_nodes[record(c.fine[1]).bullet];
    } else {  // the hanging fine node to the midpoint of two nodes: near, the coarse one and its corner's; far, the
              // kept fine one and the diagonal corner's (make_vertex_interface)
      const TreeId hanging = c.fine[c.kept == 0 ? 1 : 0];
      const TreeId first = c.kind == InterfaceKind::kVertexNear ? c.coarse : c.fine[static_cast<std::size_t>(c.kept)];
      TreeId at_corner = kNoTreeNode;
      if (c.corner_leaf != kNoTreeNode) {
        const LodNode& corner = tree().node(c.corner_leaf);
        at_corner = holding(corner.gx, corner.gy, true);
        if (record(at_corner).rest_position() != record(c.corner_leaf).rest_position()) at_corner = kNoTreeNode;
      }
      if (at_corner == kNoTreeNode) {  // no node rests there (it hangs on a coarser block): near, a plain link
        if (c.kind == InterfaceKind::kVertexFar) {
          p.c0 = 0;
          continue;
        }
        at_corner = c.coarse;
        rest = (record(hanging).rest_position() - record(c.coarse).rest_position()).length();
      } else {
        corner = at_corner;
      }
      p.coarse = &body_.m_nodes[record(hanging).bullet];
      p.fine[0] = &body_.m_nodes[record(first).bullet];
      p.fine[1] = &body_.m_nodes[record(at_corner).bullet];
    }
    // Position-based dynamics for C(x) = |(x_f0 + x_f1)/2 - x_c| - rest: gradients -n for the coarse node and n/2
    // for each fine one, so the generalised inverse mass is w_c + (w_f0 + w_f1)/4 (w_c + w_f when both are one
    // node). As for a link, the blend weight divides the constant (docs/design.md, "Blending through m_c0").
    p.inverse_mass = {p.coarse->m_im, p.fine[0]->m_im, p.fine[1]->m_im};
    const btScalar w = p.fine[0] == p.fine[1] ? p.coarse->m_im + p.fine[0]->m_im
                                              : p.coarse->m_im + btScalar(0.25) * (p.fine[0]->m_im + p.fine[1]->m_im);
    const double alpha = blend_alpha(link_meta_[static_cast<std::size_t>(c.links[0])]);
    if (solver_.compliant_model()) {  // (the far kind, an interpolated point, without compliance: w alone)
      p.c0 = w > 0 ? compliant_constant(w, interface_link_stiffness(c, corner), alpha) : btScalar(0);
      p.compliance = compliance_in_constant(p.c0, w);
    } else
      p.c0 = w > 0 ? static_cast<btScalar>(w / c.stiffness / alpha) : btScalar(0);
    p.c1 = rest * rest;
  }
  interfaces_prepared_ = inflight_.empty();  // (a blending link's weight moves at every boundary)
}

namespace {

double squared(const Eigen::Vector3d& v) { return v.squaredNorm(); }
btScalar squared(const btVector3& v) { return v.length2(); }

/// Bullet's link projection (btSoftBody::PSolve_Links: the square-root-free correction k) with the fine end at the
/// midpoint of f0 and f1, the correction shared half and half; in Bullet's floats or in the compliant material's
/// doubles (compliant_solver.h).
template <class Vector, class Scalar>
void project_interface(Vector& c, Vector& f0, Vector& f1, Scalar im_c, Scalar im_f0, Scalar im_f1, Scalar c0,
                       Scalar c1) {
  const Vector del = (f0 + f1) * Scalar(0.5) - c;
  const Scalar len = squared(del);
  if (c1 + len <= SIMD_EPSILON) return;
  const Scalar k = (c1 - len) / (c0 * (c1 + len));
  c -= del * (k * im_c);
  f0 += del * (k * Scalar(0.5) * im_f0);
  f1 += del * (k * Scalar(0.5) * im_f1);
}

/// The compliant material's interface projection with more than one pass a small step: XPBD, lambda summed over the
/// small step's passes. The square-root-free correction's (rl^2 - d^2) / (rl^2 + d^2) d stands for rl - d (-C, the
/// same near rest), less alpha~ lambda; with lambda = 0 it is project_interface's correction.
void project_interface_accumulating(Eigen::Vector3d& c, Eigen::Vector3d& f0, Eigen::Vector3d& f1, double im_c,
                                    double im_f0, double im_f1, double c0, double c1, double compliance,
                                    double& lambda) {
  const Eigen::Vector3d del = (f0 + f1) * 0.5 - c;
  const double len = del.squaredNorm();
  if (c1 + len <= SIMD_EPSILON) return;
  const double d = std::sqrt(len);
  double k = (c1 - len) / (c0 * (c1 + len));
  if (d > SIMD_EPSILON) k -= compliance * lambda / (d * c0);
  lambda += k * d;
  c -= del * (k * im_c);
  f0 += del * (k * 0.5 * im_f0);
  f1 += del * (k * 0.5 * im_f1);
}

}  // namespace

void TcSoftBody::Impl::project_interfaces() {
  for (const PreparedInterface& p : prepared_interfaces_) {
    if (p.c0 <= 0) continue;
    project_interface(p.coarse->m_x, p.fine[0]->m_x, p.fine[1]->m_x, p.inverse_mass[0], p.inverse_mass[1],
                      p.inverse_mass[2], p.c0, p.c1);
  }
}

void TcSoftBody::Impl::project_interfaces(SubstepPositions& x) {
  const Node* base = &body_.m_nodes[0];
  const bool accumulate = !x.constraint_lambda.empty();  // (more than one pass a small step: solve_constraints)
  for (std::size_t i = 0; i < prepared_interfaces_.size(); ++i) {
    const PreparedInterface& p = prepared_interfaces_[i];
    if (p.c0 <= 0) continue;
    const auto c = static_cast<std::size_t>(p.coarse - base), f0 = static_cast<std::size_t>(p.fine[0] - base),
               f1 = static_cast<std::size_t>(p.fine[1] - base);
    if (accumulate)
      project_interface_accumulating(x.x[c], x.x[f0], x.x[f1], x.inverse_mass[c], x.inverse_mass[f0],
                                     x.inverse_mass[f1], static_cast<double>(p.c0), static_cast<double>(p.c1),
                                     p.compliance, x.constraint_lambda[i]);
    else
      project_interface(x.x[c], x.x[f0], x.x[f1], x.inverse_mass[c], x.inverse_mass[f0], x.inverse_mass[f1],
                        static_cast<double>(p.c0), static_cast<double>(p.c1));
  }
}

void TcSoftBody::Impl::solve_constraints() {
  if (solver_.compliant_model()) {  // the compliant material's small steps, the interfaces in every one of them
    prepare_interfaces();
    substep_positions_.constraint_lambda.resize(solver_.compliant.passes > 1 ? prepared_interfaces_.size() : 0);
    solve_in_substeps(body_, solver_, substep_positions_, [this](SubstepPositions& x) { project_interfaces(x); });
    return;
  }
  if (interfaces_.empty()) {
    body_.btSoftBody::solveConstraints();
    return;
  }
  // Bullet's btSoftBody::solveConstraints, step for step, with the interfaces projected after the configured position
  // solvers of every iteration; the interface handles (m_c0 = 0) take no part in the velocity solve. The cluster
  // steps stay although TC-SB has no clusters: they cost what they cost a plain body (two node-sized arrays
  // allocated and zeroed), so the comparison stays fair.
  body_.applyClusters(false);
  for (int i = 0; i < body_.m_links.size(); ++i) {
    Link& l = body_.m_links[i];
    l.m_c3 = l.m_n[1]->m_q - l.m_n[0]->m_q;
    l.m_c2 = l.m_c0 > 0 ? 1 / (l.m_c3.length2() * l.m_c0) : btScalar(0);
  }
  prepare_anchors(body_);
  prepare_interfaces();
  if (body_.m_cfg.viterations > 0) {
    for (int iteration = 0; iteration < body_.m_cfg.viterations; ++iteration)
      for (int s = 0; s < body_.m_cfg.m_vsequence.size(); ++s) body_.getSolver(body_.m_cfg.m_vsequence[s])(&body_, 1);
    for (int i = 0; i < body_.m_nodes.size(); ++i)
      body_.m_nodes[i].m_x = body_.m_nodes[i].m_q + body_.m_nodes[i].m_v * body_.m_sst.sdt;
  }
  if (body_.m_cfg.piterations > 0) {
    for (int iteration = 0; iteration < body_.m_cfg.piterations; ++iteration) {
      const btScalar ti = iteration / static_cast<btScalar>(body_.m_cfg.piterations);
      for (int s = 0; s < body_.m_cfg.m_psequence.size(); ++s)
        body_.getSolver(body_.m_cfg.m_psequence[s])(&body_, 1, ti);
      project_interfaces();
    }
    const btScalar vc = body_.m_sst.isdt * (1 - body_.m_cfg.kDP);
    for (int i = 0; i < body_.m_nodes.size(); ++i) {
      Node& n = body_.m_nodes[i];
      n.m_v = (n.m_x - n.m_q) * vc;
      n.m_f = btVector3(0, 0, 0);
    }
  }
  if (body_.m_cfg.diterations > 0) {
    const btScalar vcf = body_.m_cfg.kVCF * body_.m_sst.isdt;
    for (int i = 0; i < body_.m_nodes.size(); ++i) body_.m_nodes[i].m_q = body_.m_nodes[i].m_x;
    for (int iteration = 0; iteration < body_.m_cfg.diterations; ++iteration) {
      for (int s = 0; s < body_.m_cfg.m_dsequence.size(); ++s)
        body_.getSolver(body_.m_cfg.m_dsequence[s])(&body_, 1, 0);
      project_interfaces();
    }
    for (int i = 0; i < body_.m_nodes.size(); ++i)
      body_.m_nodes[i].m_v += (body_.m_nodes[i].m_x - body_.m_nodes[i].m_q) * vcf;
  }
  body_.dampClusters();
  body_.applyClusters(true);
}

}  // namespace tcsb
