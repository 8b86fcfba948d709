// What the world pass (world/world_runner.h) shows of a method's scene as it steps, for whoever records it (`tcsb
// frames` of a scene of many bodies, world/world_frames.h). The pass calls the observer outside every timed interval
// and hands it only what it computed anyway, plus the levels when asked for, so observing changes none of its figures.
#pragma once

#include <Eigen/Core>

#include <span>
#include <string>
#include <vector>

namespace tcsb {

/// One method's scene after some steps.
struct WorldStepView {
  const std::string& method;  ///< as WorldMethodResult::method
  double budget = 1.0;        ///< as WorldMethodResult::budget
  int steps = 0;              ///< steps done, warm-up included (0: the initial state)
  /// Per body (scene order): its surface at the fine net's grid points as the pass measures it (TC-SB geomorphed).
  std::span<const std::vector<Eigen::Vector3d>> surfaces;
  /// Per body, per grid point: the LOD level governing it (TC-SB: the committed cut's block holding it; discrete LOD:
  /// the body's grid, 0 the net, each level a quarter of the nodes of the one before; full resolution: 0).
  std::span<const std::vector<int>> levels;
  int nodes = 0;  ///< simulated nodes of every body, summed
};

class WorldObserver {
 public:
  virtual ~WorldObserver() = default;
  /// Whether observe() wants `method`'s scene after `steps` steps: the levels are found only then.
  virtual bool wants(const std::string& method, int steps) const = 0;
  virtual void observe(const WorldStepView& view) = 0;
};

}  // namespace tcsb
