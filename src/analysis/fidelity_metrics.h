// Fidelity metrics: how far a reconstructed full-resolution surface lies from the reference's, and the mechanical
// energy of a body. Pure functions on flat arrays (no Bullet), evaluated once per step by the fidelity pass.
#pragma once

#include <Eigen/Core>

#include <span>

namespace tcsb {

/// Distances between a surface and the reference, node by node, in the units of the positions (metres).
struct SurfaceError {
  double rms = 0;  ///< sqrt(mean |x_i - ref_i|^2)
  double max = 0;  ///< max |x_i - ref_i|
  /// sqrt(sum w_i |x_i - ref_i|^2 / sum w_i): the error where the weights (the reference's saliency) say it is
  /// seen. Equals rms when no weights are given or they sum to 0 (nothing salient: every node counts the same).
  double weighted_rms = 0;
};

/// Node-by-node error of `surface` against `reference` (same size), optionally weighted by `weights` (empty, or one
/// non-negative finite weight per node). Throws std::invalid_argument on mismatched sizes or a bad weight; zero
/// for empty surfaces.
SurfaceError surface_error(std::span<const Eigen::Vector3d> surface, std::span<const Eigen::Vector3d> reference,
                           std::span<const float> weights = {});

/// The largest distance any node moved between two states of the same surface (popping at a step boundary, where
/// no simulated time passes). Throws std::invalid_argument on mismatched sizes.
double max_displacement(std::span<const Eigen::Vector3d> before, std::span<const Eigen::Vector3d> after);

/// Mechanical energy sum m_i (|v_i|^2 / 2 + g y_i), joules, with gravity g along -y and y measured from 0 (not from
/// the rest plane, so a body at rest at height h has energy M g h). Throws std::invalid_argument on mismatched sizes.
double mechanical_energy(std::span<const double> mass, std::span<const Eigen::Vector3d> position,
                         std::span<const Eigen::Vector3d> velocity, double gravity);

/// 100 |energy - reference| / |scale|: how far a body's energy is from the reference's at the same step, in percent
/// of `scale` — the reference's initial energy, not its current one: the paper's stretchy nets fall through y = 0
/// (n81's centre reaches -7.9 m), so the current energy crosses zero and would make any difference look infinite.
/// NaN when scale is 0 (undefined: the caller leaves that step out). Total masses being equal, the difference does
/// not depend on where y = 0 is; only the scale does.
double energy_drift_pct(double energy, double reference, double scale);

}  // namespace tcsb
