#include "softbody/compliant_solver.h"

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBodyInternals.h>

#include <algorithm>
#include <cmath>

#include "softbody/tc_softbody.h"
#include "softbody/vector_conversion.h"

namespace tcsb {

void keep_start_velocities(btSoftBody& body) {
  for (int i = 0; i < body.m_nodes.size(); ++i) body.m_nodes[i].m_vn = body.m_nodes[i].m_v;
}

void prepare_anchors(btSoftBody& body) {
  for (int i = 0; i < body.m_anchors.size(); ++i) {
    btSoftBody::Anchor& a = body.m_anchors[i];
    const btVector3 ra = a.m_body->getWorldTransform().getBasis() * a.m_local;
    a.m_c0 =
        ImpulseMatrix(body.m_sst.sdt, a.m_node->m_im, a.m_body->getInvMass(), a.m_body->getInvInertiaTensorWorld(), ra);
    a.m_c1 = ra;
    a.m_c2 = body.m_sst.sdt * a.m_node->m_im;
    a.m_body->activate();
  }
}

namespace {

/// One pass over the links, in the links' order, on the double positions: XPBD's correction, each link moved along
/// itself by its change of lambda, (rl - d - alpha~ lambda) / m_c0 (XPBD: Macklin, Müller and Chentanez, MIG 2016,
/// with the constraint's gradient along the link). Not btSoftBody::PSolve_Links' square-root-free (rl^2 - d^2) / (m_c0
/// (rl^2 + d^2)), the same near rest but 1.2 x at twice the rest length: with it the 97 x 97 flag at 12 small steps
/// diverged at step 58 (the body 92 m wide), with this one it did not (nor at 16).
///
/// kAccumulateLambda false (one pass a small step): lambda = 0, the expression as before passes existed, bit for
/// bit. True: each link's lambda summed over the small step's passes in p.link_lambda, and alpha~ the part of m_c0
/// that is not the endpoints' inverse masses (compliance_in_constant), so the passes converge to the implicit Euler
/// step of the material's springs instead of to a stiffer cloth or a softer one.
template <bool kAccumulateLambda>
void solve_links(const btSoftBody& body, SubstepPositions& p) {
  const btSoftBody::Node* base = &body.m_nodes[0];
  for (int i = 0; i < body.m_links.size(); ++i) {
    const btSoftBody::Link& l = body.m_links[i];
    if (!(l.m_c0 > 0)) continue;
    const auto a = static_cast<std::size_t>(l.m_n[0] - base), b = static_cast<std::size_t>(l.m_n[1] - base);
    const Eigen::Vector3d del = p.x[b] - p.x[a];
    const double length = del.norm();
    if (length <= SIMD_EPSILON) continue;
    const double c0 = static_cast<double>(l.m_c0);
    if constexpr (kAccumulateLambda) {
      double& lambda = p.link_lambda[static_cast<std::size_t>(i)];
      const double alpha_tilde = compliance_in_constant(c0, p.inverse_mass[a] + p.inverse_mass[b]);
      const double k = (static_cast<double>(l.m_rl) - length - alpha_tilde * lambda) / (length * c0);
      lambda += k * length;
      p.x[a] -= del * (k * p.inverse_mass[a]);
      p.x[b] += del * (k * p.inverse_mass[b]);
    } else {
      const double k = (static_cast<double>(l.m_rl) - length) / (length * c0);
      p.x[a] -= del * (k * p.inverse_mass[a]);
      p.x[b] += del * (k * p.inverse_mass[b]);
    }
  }
}

/// Runs one of Bullet's own position solvers (anchors, rigid or soft contacts) on the nodes it moves: their float
/// positions from the double ones first, and what it moved them by added to the double ones after. `nodes` lists
/// them (a node may be listed twice).
template <class Nodes>
void run_bullet_solver(btSoftBody& body, btSoftBody::ePSolver::_ solver, btScalar ti, SubstepPositions& p,
                       const Nodes& nodes) {
  btSoftBody::Node* base = &body.m_nodes[0];
  nodes([&](btSoftBody::Node* n) {
    const auto i = static_cast<std::size_t>(n - base);
    n->m_x = to_bullet(p.x[i]);
    n->m_q = to_bullet(p.q[i]);
  });
  btSoftBody::getSolver(solver)(&body, 1, ti);
  nodes([&](btSoftBody::Node* n) {
    const auto i = static_cast<std::size_t>(n - base);
    p.x[i] += to_eigen(n->m_x) - to_eigen(to_bullet(p.x[i]));  // (0 for a node listed again)
  });
}

}  // namespace

void solve_in_substeps(btSoftBody& body, const SolverSettings& solver, SubstepPositions& p,
                       const std::function<void(SubstepPositions&)>& after_links) {
  const int n = solver.compliant.substeps;
  const btScalar dt = body.m_sst.sdt;  // predictMotion's
  const double h = static_cast<double>(dt) / n;
  const auto count = static_cast<std::size_t>(body.m_nodes.size());
  p.x.resize(count);
  p.q.resize(count);
  p.inverse_mass.resize(count);
  // predictMotion added the step's forces to the velocities and advanced the positions a whole step for the
  // collision detection: back to the step's start, with each node's velocity change per small step in m_vn.
  const btScalar per_substep = btScalar(1) / static_cast<btScalar>(n);
  for (std::size_t i = 0; i < count; ++i) {
    btSoftBody::Node& node = body.m_nodes[static_cast<int>(i)];
    const btVector3 start = node.m_vn;
    node.m_vn = (node.m_v - start) * per_substep;
    node.m_v = start;
    p.x[i] = to_eigen(node.m_q);
    p.inverse_mass[i] = node.m_im;
  }
  // The contacts' constants were made for the whole step (ImpulseMatrix of sdt, and sdt x the inverse mass): their
  // product, the node's correction, does not depend on it, but the impulse a dynamic rigid body receives does.
  // Their hardness (m_c4: the share of the distance to the contact plane a solve closes, Bullet's kCHR or kKHR) is a
  // step's too: closed in every small step it would move a node n times as far, and v = (x - q) / h would turn each
  // small step's pull into n times the velocity a step gives it.
  for (int i = 0; i < body.m_rcontacts.size(); ++i) {
    btSoftBody::RContact& c = body.m_rcontacts[i];
    c.m_c0 = c.m_c0 * static_cast<btScalar>(n);
    c.m_c2 *= per_substep;
    c.m_c4 *= per_substep;
  }
  body.m_sst.sdt = static_cast<btScalar>(h);
  body.m_sst.isdt = static_cast<btScalar>(1 / h);
  prepare_anchors(body);
  const double keep = std::exp(-solver.compliant.damping * h);
  const double velocity_scale = keep / h, pin_velocity_scale = 1 / h;  // (a pin moves as its path says: undamped)
  const auto anchored = [&](const auto& f) {
    for (int i = 0; i < body.m_anchors.size(); ++i) f(body.m_anchors[i].m_node);
  };
  const auto in_contact = [&](const auto& f) {
    for (int i = 0; i < body.m_rcontacts.size(); ++i) f(body.m_rcontacts[i].m_node);
  };
  const auto every_node = [&](const auto& f) {
    for (int i = 0; i < body.m_nodes.size(); ++i) f(&body.m_nodes[i]);
  };
  // One pass: lambda = 0 in it, nothing to keep. More: lambda summed over the passes of each small step.
  const int passes = solver.compliant.passes;
  const bool accumulate = passes > 1;
  p.link_lambda.resize(accumulate ? static_cast<std::size_t>(body.m_links.size()) : 0);
  for (int s = 0; s < n; ++s) {
    for (std::size_t i = 0; i < count; ++i) {
      btSoftBody::Node& node = body.m_nodes[static_cast<int>(i)];
      p.q[i] = p.x[i];
      node.m_v += node.m_vn;
      p.x[i] += to_eigen(node.m_v) * h;
    }
    if (accumulate) {  // each small step is an implicit Euler step of its own: its lambda starts from 0
      std::fill(p.link_lambda.begin(), p.link_lambda.end(), 0.0);
      std::fill(p.constraint_lambda.begin(), p.constraint_lambda.end(), 0.0);
    }
    const btScalar ti = static_cast<btScalar>(s) / static_cast<btScalar>(n);
    for (int pass = 0; pass < passes; ++pass) {
      for (int k = 0; k < body.m_cfg.m_psequence.size(); ++k) {
        const btSoftBody::ePSolver::_ which = body.m_cfg.m_psequence[k];
        if (which == btSoftBody::ePSolver::Linear) {
          if (accumulate)
            solve_links<true>(body, p);
          else
            solve_links<false>(body, p);
          continue;
        }
        // Anchors and contacts once a small step: their hardness is the small step's share of the step's, and
        // solved again in every pass it would pull a node `passes` times as far.
        if (pass > 0) continue;
        switch (which) {
          case btSoftBody::ePSolver::Anchors:
            if (body.m_anchors.size() > 0) run_bullet_solver(body, which, ti, p, anchored);
            break;
          case btSoftBody::ePSolver::RContacts:
            if (body.m_rcontacts.size() > 0) run_bullet_solver(body, which, ti, p, in_contact);
            break;
          default:
            if (body.m_scontacts.size() > 0) run_bullet_solver(body, which, ti, p, every_node);
            break;
        }
      }
      if (after_links) after_links(p);
    }
    for (std::size_t i = 0; i < count; ++i) {
      btSoftBody::Node& node = body.m_nodes[static_cast<int>(i)];
      node.m_v = to_bullet((p.x[i] - p.q[i]) * (node.m_im > 0 ? velocity_scale : pin_velocity_scale));
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    btSoftBody::Node& node = body.m_nodes[static_cast<int>(i)];
    node.m_x = to_bullet(p.x[i]);
    node.m_q = to_bullet(p.q[i]);
    node.m_f = btVector3(0, 0, 0);
  }
  body.m_sst.sdt = dt;
  body.m_sst.isdt = 1 / dt;
}

double grid_link_stiffness(const SolverSettings& solver, double adjacent, double length, double spacing_along,
                           double spacing_across) {
  const double area = adjacent * spacing_along * spacing_across;
  return membrane_link_stiffness(solver.compliant.stretch_stiffness, area, length * spacing_along);
}

void write_compliant_grid_constants(btSoftBody& body, const Net& net, const SolverSettings& solver) {
  const int w = net.width(), h = net.height();
  const double hx = net.spec().size_x / (w - 1), hz = net.spec().size_z / (h - 1);
  const std::span<const NetLink> links = net.links();
  for (std::size_t i = 0; i < links.size(); ++i) {
    const NetLink& l = links[i];
    if (l.kind != LinkKind::kStructural)
      throw std::invalid_argument("the compliant material has structural links only (no shear or bend links)");
    const int xa = l.a % w, za = l.a / w, xb = l.b % w;
    const bool along_x = xb != xa;
    // The cells on either side of the link: two inside the grid, one on its border.
    const int across = along_x ? za : xa, last = along_x ? h - 1 : w - 1;
    const double adjacent = (across > 0 ? 1.0 : 0.0) + (across < last ? 1.0 : 0.0);
    const double k =
        along_x ? grid_link_stiffness(solver, adjacent, 1, hx, hz) : grid_link_stiffness(solver, adjacent, 1, hz, hx);
    btSoftBody::Link& link = body.m_links[static_cast<int>(i)];
    const btScalar w_ab = link.m_n[0]->m_im + link.m_n[1]->m_im;
    link.m_c0 = static_cast<btScalar>(compliant_link_constant(w_ab, k, solver.substep_dt()));
  }
}

const SolverSettings* compliant_settings(const btSoftBody& body) {
  if (const auto* tc = dynamic_cast<const TcSoftBody*>(&body))
    return tc->solver().compliant_model() ? &tc->solver() : nullptr;
  if (const auto* c = dynamic_cast<const CompliantSoftBody*>(&body)) return &c->solver();
  return nullptr;
}

}  // namespace tcsb
