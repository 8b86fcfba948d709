// Shared fixtures for the soft-body tests: a net, a world, and bodies built from them.
#pragma once

#include <LinearMath/btScalar.h>

#include <memory>

#include "net/net.h"
#include "scene/scene_world.h"
#include "softbody/solver_settings.h"

namespace tcsb::testing {

/// The step every soft-body test takes: Bullet's usual 60 Hz.
inline constexpr btScalar kDt = 1.0f / 60;

inline std::shared_ptr<const Net> square_net(int width, unsigned pinned = kAllCorners,
                                             RestPlacement rest = RestPlacement::kCentroid) {
  NetSpec spec;
  spec.name = "test";
  spec.width = spec.height = width;
  spec.pinned_corners = pinned;
  return std::make_shared<const Net>(spec, rest);
}

inline SolverSettings test_solver() {
  SolverSettings s;
  s.piterations = 2;
  return s;
}

}  // namespace tcsb::testing
