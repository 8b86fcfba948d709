// Discrete levels of detail: what a game does today instead of TC-SB. Each cloth has a few precomputed grids, the
// finest first (level 0, the net itself), and shows the one its distance from the camera selects, switching at
// distance thresholds; at a switch the state is resampled onto the new grid (its pop is measured as TC-SB's is).
//
// The thresholds follow the usual rule: a level is used out to where its cells look as small on the image as the
// next coarser level's do at its own threshold, so with each level's spacing twice the last's, each threshold is
// twice the one before it (d_k = scale x 2^(k-1)), and one number, `scale`, sets them all. fit_discrete_lod() picks the
// scale at which the mean node count over a run equals a budget, so discrete LOD and TC-SB are compared at the same
// mean node count. A game also keeps a margin against flicker: a body switches coarser only beyond (1 + hysteresis)
// x its threshold and finer only inside (1 - hysteresis) x it.
//
// Pure arithmetic on distances the caller computes (camera to body centre, per step and body).
#pragma once

#include <span>
#include <vector>

namespace tcsb {

struct DiscreteLod {
  double scale = 1;         ///< distance, metres, beyond which level 1 replaces level 0; level k's is scale x 2^(k-1)
  double hysteresis = 0.1;  ///< the margin against flicker, a fraction of the threshold, in [0, 1)
  int levels = 1;           ///< grids available: levels 0 .. levels - 1

  /// The level a body at `distance` shows, having shown `current` (the level the thresholds give, except within the
  /// hysteresis margin of the threshold it would cross, where it keeps `current`).
  int level(double distance, int current) const;
  /// The level at `distance` without history (a body's first step).
  int level(double distance) const;
};

/// The levels a schedule of distances gives: distances[s * bodies + b] is body b's distance at step s; the result has
/// the same layout. Each body starts at the level its first distance gives, then follows DiscreteLod::level.
std::vector<int> lod_schedule(const DiscreteLod& lod, std::span<const double> distances, std::size_t bodies);

/// The discrete LOD whose mean over steps of the summed node count is the largest at most `budget`:
/// level_nodes[k] is one body's node count at level k (finest first, levels = level_nodes.size()), `distances` as
/// lod_schedule's. The mean is a step function of the scale, non-decreasing; found by bisection to a relative 1e-9.
/// When even the coarsest everywhere exceeds the budget, the scale 0 (every body coarsest beyond 0 m). Throws
/// std::invalid_argument when level_nodes is empty, distances is not a whole number of steps, or hysteresis is
/// outside [0, 1).
DiscreteLod fit_discrete_lod(std::span<const int> level_nodes, std::span<const double> distances, std::size_t bodies,
                             double budget, double hysteresis);

/// Mean over steps of the summed node count of a schedule (lod_schedule's layout).
double mean_lod_nodes(std::span<const int> levels, std::span<const int> level_nodes, std::size_t bodies);

}  // namespace tcsb
