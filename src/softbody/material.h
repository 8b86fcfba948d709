// Material: what the cloth is made of, and how its links are solved. Two models (docs/design.md, "The material"):
//
//  * kBullet — Bullet's own: every link corrected by the material's kLST, `piterations` Gauss-Seidel passes a step.
//    The stiffness a cloth shows then depends on the iteration count and on the resolution (a coarse net converges
//    faster and is stiffer), which is why `tcsb calibrate` fits one kLST per level.
//  * kCompliant — one physical material at every level: a membrane stiffness Y (N/m) and a density (kg/m^2), each
//    link's compliance from the 2D rule (k_e = Y x the area of its adjacent cells / (2 x its length^2): Van Gelder,
//    JGT 1998), masses lumped by area, and each step taken as `substeps` small steps of `passes` link passes each
//    (XPBD: Macklin et al., "Small Steps in Physics Simulation", SCA 2019; one pass is XPBD with lambda = 0, more
//    accumulate each link's lambda over the small step's passes), with Bullet's link constant
//    m_c0 = w_a + w_b + alpha / h^2 as XPBD's denominator (compliant_solver.h runs the passes on positions in double
//    precision).
#pragma once

namespace tcsb {

/// Which material model a suite's bodies use.
enum class MaterialModel {
  kBullet,     ///< Bullet's kLST and piterations (SolverSettings): the paper's, and every suite's default
  kCompliant,  ///< CompliantMaterial: compliant links in small steps, the same material at every level
};

/// The most link passes a small step may take: as many as Bullet's iterations may be (solver.piterations); past a
/// few the passes cost more than the small steps they could replace.
inline constexpr int kMaxLinkPasses = 1000;

/// The compliant model's cloth, in physical units.
struct CompliantMaterial {
  double stretch_stiffness = 100.0;  ///< membrane stiffness Y, N/m (tension per unit width at unit strain)
  double density = 0.1;              ///< areal density, kg/m^2: node masses lumped by area
  /// Velocity damping rate, 1/s: each small step of h keeps exp(-damping h) of the velocity, so a second damps the
  /// same whatever the substep count.
  double damping = 0.0;
  int substeps = 16;  ///< small steps per step
  /// Link passes per small step. One is XPBD with lambda = 0, a link of stiffness k / (1 + k h^2 w) (w: its
  /// endpoints' inverse masses), softer than the material where k h^2 w is not small; more accumulate each link's
  /// lambda over the small step's passes, which converges to the implicit Euler step, whose rest is the material's.
  int passes = 1;
};

/// Whose stiffness a link of the compliant model carries: the membrane stiffness times the area of the cells on
/// either side of it over twice its squared length, N/m (the 2D rule; a link inside a regular grid carries Y, a
/// link on the border, with one cell, Y/2). Lengths and areas in metres and square metres.
inline double membrane_link_stiffness(double stretch_stiffness, double adjacent_area, double length) {
  return stretch_stiffness * adjacent_area / (2.0 * length * length);
}

/// Bullet's link constant m_c0 for a compliant link: the endpoints' inverse masses plus the link's compliance over
/// the small step squared (alpha~ = 1 / (k h^2)), XPBD's denominator w + alpha~: a pass moves the link by
/// (rl - d) / m_c0 (compliant_solver.h).
inline double compliant_link_constant(double inverse_masses, double stiffness, double substep_dt) {
  return inverse_masses + 1.0 / (stiffness * substep_dt * substep_dt);
}

/// The compliance over the small step squared (alpha~, XPBD's) that a compliant link constant stands for, given the
/// inverse masses it was made with: m_c0 - w, never below 0 (m_c0 is a float). A blend divides m_c0 by its weight b,
/// and its constant then stands for a softer link, alpha~ / b + w (1 - b) / b: one pass corrects it by b of the
/// whole link's correction, and passes that accumulate lambda converge to a spring that fades with b.
inline double compliance_in_constant(double constant, double inverse_masses) {
  return constant > inverse_masses ? constant - inverse_masses : 0.0;
}

}  // namespace tcsb
