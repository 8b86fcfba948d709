#include "softbody/plain_softbody.h"

#include <BulletSoftBody/btSoftBodyHelpers.h>

#include <stdexcept>

#include "softbody/bullet_setup.h"
#include "softbody/compliant_solver.h"

namespace tcsb {

std::unique_ptr<btSoftBody> make_plain_softbody(btSoftBodyWorldInfo& world, const Net& net,
                                                const SolverSettings& settings) {
  check_solver_settings(settings);
  std::unique_ptr<btSoftBody> body;
  if (settings.compliant_model())
    body = std::make_unique<CompliantSoftBody>(world, settings);
  else
    body = std::make_unique<btSoftBody>(&world, 0, nullptr, nullptr);
  init_net_nodes(*body, net);
  apply_solver_settings(*body, settings);
  append_net_links(*body, net);
  if (settings.compliant_model()) write_compliant_grid_constants(*body, net, settings);
  return body;
}

std::unique_ptr<btSoftBody> make_bullet_patch(btSoftBodyWorldInfo& world, const Net& net,
                                              const SolverSettings& settings) {
  const NetSpec& s = net.spec();
  if (s.shear_links || s.bend_links)
    throw std::invalid_argument("bullet_patch: CreatePatch makes structural links only");
  const btScalar hx = static_cast<btScalar>(0.5 * s.size_x), hz = static_cast<btScalar>(0.5 * s.size_z);
  const btScalar y = static_cast<btScalar>(s.elevation);
  std::unique_ptr<btSoftBody> body(btSoftBodyHelpers::CreatePatch(
      world, btVector3(-hx, y, -hz), btVector3(hx, y, -hz), btVector3(-hx, y, hz), btVector3(hx, y, hz), s.width,
      s.height, static_cast<int>(s.pinned_corners), /*gendiags=*/false));
  apply_solver_settings(*body, settings);
  // The paper's mass-spring model has nodes and links only, and so do the plain baseline and TC-SB; CreatePatch's
  // faces would add per-step face work (normals, aero no-ops, areas: ~15% at these sizes) that no compared body
  // does. Dropping them leaves CreatePatch's own nodes, links, order and constants: the check is then on equal work.
  body->m_faces.resize(0);
  // CreatePatch gives every node mass 1; scale to the net's masses so both bodies are the same cloth (uniform
  // masses: only the ratio of inverse masses enters the link solver, so this changes no position).
  // CreatePatch pins corners only; the net's other pins (an edge, listed nodes) get Bullet's zero inverse mass here.
  for (int i = 0; i < body->m_nodes.size(); ++i) {
    btSoftBody::Node& n = body->m_nodes[i];
    if (net.pinned()[static_cast<std::size_t>(i)])
      n.m_im = 0;
    else if (n.m_im > 0)
      n.m_im = static_cast<btScalar>(1.0 / net.masses()[static_cast<std::size_t>(i)]);
  }
  body->updateConstants();
  body->m_bUpdateRtCst = false;
  return body;
}

}  // namespace tcsb
