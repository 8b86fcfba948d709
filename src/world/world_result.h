// WorldResult: what the world pass measured of a scene of many bodies (world/world_runner.h), each method's bodies
// stepped side by side in one world of their own.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tcsb {

/// Operations TC-SB bodies began over the measured steps (world/cut_churn.h), summed over a scene's bodies.
struct ChurnCounts {
  long long refines = 0;   ///< refines begun
  long long coarsens = 0;  ///< coarsens begun
  /// Of those, the ones that undid the last operation begun on the same block within the window: a coarsen of a
  /// block refined, or a refine of a block coarsened, within the pass's churn window (two evaluation intervals).
  long long undone = 0;
  /// Boundaries at which the body's committed nodes moved against their last move, made within the window: its
  /// share of the detail going up and down.
  long long reversals = 0;
  /// The committed nodes' changes, |after - before| a boundary, summed: a third of it (a block adds or removes three
  /// nodes) is the operations that moved detail between bodies or to and from the budget; the rest of the
  /// operations traded detail within a body.
  long long nodes_moved = 0;
};

/// One method over the whole scene.
struct WorldMethodResult {
  /// "full_resolution" (the first row, solver_divisor 1, is the reference), "tcsb_world", "tcsb_body",
  /// "discrete_lod", or with fidelity.curves "noise_floor": the reference started perturbed, whose error is what no
  /// method can be measured more finely than (fidelity/fidelity_floors.h).
  std::string method;
  double budget = 1.0;        ///< node budget as a fraction of the scene's nodes (1 for full resolution)
  int solver_divisor = 1;     ///< full resolution on the curve of fewer passes: the suite's passes a step divided
  std::string status = "ok";  ///< "ok" or "diverged"
  std::optional<int> diverged_step;
  std::string diverged_reason;
  double mean_nodes = 0;                ///< simulated nodes of every body, summed, mean over the measured steps
  std::vector<double> body_mean_nodes;  ///< per body (scene order), mean over the measured steps
  double step_ms = 0;                   ///< mean step of the whole scene, milliseconds
  /// The part of step_ms spent before the world steps: TC-SB's blends, feedback and operations (and the world
  /// budget's split), discrete LOD's switches; the rest is Bullet's step and the controllers' after_step.
  double boundary_ms = 0;
  std::vector<double> block_step_ms;  ///< per block of measured steps, its mean step
  /// Median over blocks of this method's block mean over full resolution's of the same block (same run).
  double step_ratio = 1.0;
  /// Per measured step the 95th percentile over every visible reference point of every body of the distance on the
  /// image to where this method puts it, pixels; the mean over steps.
  double p95_px = 0;
  /// The largest jump on the image of any body's surface at a step boundary where the method changed its resolution
  /// (TC-SB: operations, and the boundaries its geomorph spreads them over; discrete LOD: a switch), pixels.
  double popping_px = 0;
  int resolution_changes = 0;        ///< those boundaries, counted per body
  std::optional<double> lod_scale;   ///< discrete LOD: the fitted distance of its first switch, metres
  std::optional<ChurnCounts> churn;  ///< TC-SB: its operations, and how many undid a recent one
};

struct WorldResult {
  int bodies = 0;
  long long scene_nodes = 0;  ///< every body's net nodes, summed
  std::vector<WorldMethodResult> methods;
  double wall_s = 0;
};

}  // namespace tcsb
