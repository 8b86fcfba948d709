// Fidelity floors: the error below which no subject can be expected to go, measured with the same metric as the
// subjects' (surface_error() against the reference's frame of each measured step), so every error of the fidelity
// pass stands beside the best achievable.
//
//  * The noise floor: the reference against itself started with every initial position perturbed by a
//    deterministic 1e-6 of the net's extent. Where the simulation is chaotic (few solver iterations), this alone
//    grows into a visible difference, and no method can be measured more finely than it.
//  * The interpolation floor: the reference's own surface sampled at the nodes of a coarse rest grid and
//    interpolated back bilinearly — the error a perfect body of that resolution (each node exactly on the reference)
//    would still show. Reported per budget, for the uniform grid of the budget's node count (coarse_grid_for()):
//    every method at that budget simulates about that many nodes.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

#include "net/grid_resample.h"

namespace tcsb {

/// Relative size of the noise floor's perturbation: a fraction of the net's extent.
inline constexpr double kNoiseFloorPerturbation = 1e-6;

/// Seed of the noise floor's perturbation of net (or scene body) 0; net k uses this + k. Any fixed value serves, it
/// only has to be the same on every run.
inline constexpr std::uint64_t kNoiseFloorSeed = 0x6e6f697365ULL;

/// Moves every node of `body` (position and previous position, pinned ones included) by a deterministic
/// pseudo-random offset, each coordinate uniform in [-amplitude, amplitude], drawn from `seed` (splitmix64, so the
/// same body and seed get the same offsets on every platform). Amplitude 0 leaves the body bit for bit unchanged.
void perturb_positions(btSoftBody& body, double amplitude, std::uint64_t seed);

/// `x` (a surface on grid `fine`) as a body on grid `coarse` that matched it exactly at its nodes would show it:
/// sampled bilinearly at the coarse nodes, then interpolated back to every fine node. `out` equals `x` exactly when
/// `coarse` is `fine`. Throws std::invalid_argument on mismatched sizes or a grid under 2 x 2.
void resample_through(GridSize fine, std::span<const Eigen::Vector3d> x, GridSize coarse,
                      std::vector<Eigen::Vector3d>& coarse_scratch, std::vector<Eigen::Vector3d>& out);

}  // namespace tcsb
