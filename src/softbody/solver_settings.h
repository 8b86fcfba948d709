// SolverSettings: the btSoftBody configuration a suite states, applied identically to every body of a run.
#pragma once

#include <algorithm>

#include "../softbody/material.h"

namespace tcsb {

/// Bullet soft-body solver settings (btSoftBody::Config and the default material). Bullet's own defaults are
/// piterations = 1, which diverges at 65x65 with fixed corners (docs/design.md, "Solver defaults"), so suites always
/// state theirs.
struct SolverSettings {
  int piterations = 2;            ///< position (link) solver iterations
  int viterations = 0;            ///< velocity solver iterations
  int diterations = 0;            ///< drift solver iterations
  double damping = 0.0;           ///< kDP, velocity damping in [0, 1)
  double linear_stiffness = 1.0;  ///< kLST of the material, in (0, 1]
  /// The material model (material.h): kBullet uses the fields above; kCompliant solves every body in `compliant`'s
  /// small steps instead (the fields above then still make the stock Bullet baseline, Method::kStock).
  MaterialModel model = MaterialModel::kBullet;
  CompliantMaterial compliant;
  /// The step the compliant links' compliance is baked for (alpha / h^2 with h = step_dt / substeps), seconds: the
  /// suite's dt. A compliant body stepped with another dt is as stiff as its constants say for this one.
  double step_dt = 1.0 / 60.0;
  bool compliant_model() const { return model == MaterialModel::kCompliant; }
  /// The small step h of the compliant model, seconds.
  double substep_dt() const { return step_dt / compliant.substeps; }
};

/// The same settings stepped by Bullet itself (MaterialModel::kBullet): stock Bullet at the suite's kLST and
/// iterations, the baseline beside a compliant suite's bodies (Method::kStock, and the fidelity pass's stock_bullet).
inline SolverSettings stock_bullet(SolverSettings settings) {
  settings.model = MaterialModel::kBullet;
  return settings;
}

/// The same settings with `substeps` small steps of the compliant material.
inline SolverSettings with_substeps(SolverSettings settings, int substeps) {
  settings.compliant.substeps = substeps;
  return settings;
}

/// The same settings with their link passes a step (the small steps under the compliant material) divided by
/// `divisor`, at least 1: a cheaper cloth without adaptivity (the fidelity pass's full-resolution curve).
inline SolverSettings with_passes_divided(SolverSettings settings, int divisor) {
  if (settings.compliant_model()) return with_substeps(settings, std::max(1, settings.compliant.substeps / divisor));
  settings.piterations = std::max(1, settings.piterations / divisor);
  return settings;
}

/// Throws std::invalid_argument naming the field ("SolverSettings: linear_stiffness must be in (0, 1], got 0") for
/// settings no body can be stepped with: the suite reader's ranges, for a program that fills the struct itself. Every
/// body factory checks with it (make_plain_softbody, TcSoftBody).
void check_solver_settings(const SolverSettings& settings);

/// World parameters shared by every body of a run.
struct WorldSettings {
  double dt = 1.0 / 60.0;  ///< fixed time step, seconds
  double gravity = 9.81;   ///< m/s^2 along -y
};

}  // namespace tcsb
