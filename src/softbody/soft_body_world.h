// SoftBodyWorld: the btSoftBodyWorldInfo every body of a case points at (gravity, air density). Bodies keep a raw
// pointer to it, so it must outlive them; the runner owns one per repetition.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include "softbody/solver_settings.h"

namespace tcsb {

/// World parameters in the form Bullet's soft bodies read them. Not copyable: bodies hold its address.
struct SoftBodyWorld {
  explicit SoftBodyWorld(const WorldSettings& settings) : settings(settings) {
    info.m_gravity.setValue(0, static_cast<btScalar>(-settings.gravity), 0);
    info.m_broadphase = nullptr;  // bodies are stepped solo, outside any collision world (docs/design.md, "One step")
    info.m_dispatcher = nullptr;
  }
  SoftBodyWorld(const SoftBodyWorld&) = delete;
  SoftBodyWorld& operator=(const SoftBodyWorld&) = delete;

  WorldSettings settings;
  btSoftBodyWorldInfo info;
};

}  // namespace tcsb
