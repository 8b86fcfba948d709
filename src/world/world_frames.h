// World frames: the world pass of a scene of many bodies (world/world_runner.h) recorded at given steps, for the
// fly-by animation (scripts/render-figures.py --animate): every body's surface as the pass reconstructs it and the
// LOD level governing each of its grid points, for TC-SB and discrete LOD at one budget. The pass runs as a run
// would (its figures unchanged, world_observer.h); nothing of it is timed here.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "net/net_spec.h"
#include "suite/suite.h"
#include "world/world_result.h"

namespace tcsb {

/// One method's scene at one frame: per body (scene order) its surface and levels (WorldStepView).
struct WorldFrameScene {
  int nodes = 0;  ///< simulated nodes of every body, summed
  std::vector<std::vector<Eigen::Vector3d>> surfaces;
  std::vector<std::vector<int>> levels;
};

/// The recorded methods after `step` steps, in WorldFrames::methods' order.
struct WorldFrame {
  int step = 0;
  std::vector<WorldFrameScene> scenes;
};

struct WorldFrames {
  double compression = 1.0;
  std::vector<NetSpec> bodies;             ///< each body's net, placed (scene_body_nets)
  std::vector<WorldMethodResult> methods;  ///< the recorded methods' summaries: TC-SB, then discrete_lod
  std::vector<WorldFrame> frames;          ///< one per requested step every recorded method reached, in step order
};

/// The methods recorded: TC-SB under the scene's one budget ("tcsb_world") where feedback.budget_scope is "world",
/// else under per-body budgets ("tcsb_body"); then "discrete_lod".
std::vector<std::string> world_frame_methods(const Suite& suite);

/// Runs the world pass of `suite` (is_world_suite) at the one budget `compression` (0 < compression < 1) and records
/// world_frame_methods() after each of `steps` (ascending, distinct, 0 the initial state, at most the suite's warm-up
/// and measured steps). A step after a method diverged is missing; the methods' summaries say where and why.
/// Throws std::invalid_argument for a suite that is not a scene of many bodies, or a compression or steps out of range.
WorldFrames record_world_frames(const Suite& suite, double compression, const std::vector<int>& steps);

}  // namespace tcsb
