// An application's own Bullet world, as a game builds it (examples/drape_tcsb.cpp): a btSoftRigidDynamicsWorld with
// the soft-body collision configuration and tcsb::TcSoftBodySolver, for the TreeCutDriver's tests.
#pragma once

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <memory>

#include "net/net.h"
#include "softbody/tc_softbody_solver.h"

namespace tcsb::testing {

struct AppWorld {
  btSoftBodyRigidBodyCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  TcSoftBodySolver cloth_solver;
  btSoftRigidDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration, &cloth_solver};

  AppWorld() {
    world.setGravity(btVector3(0, -9.81f, 0));
    world.getWorldInfo().m_gravity = world.getGravity();
    world.getWorldInfo().m_sparsesdf.setDefaultVoxelsz(0.05f);
    world.getWorldInfo().m_sparsesdf.Reset();
  }
  btSoftBodyWorldInfo& info() { return world.getWorldInfo(); }
};

/// Static ground whose top is the plane y = 0, `half` metres each way from the origin, in the app's world while it
/// lives (declare it after the AppWorld and remove the bodies lying on it first).
struct Ground {
  AppWorld& app;
  btBoxShape shape;
  btRigidBody body;

  Ground(AppWorld& world, float half)
      : app(world), shape(btVector3(half, 0.5f, half)),
        body(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &shape)) {
    body.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, -0.5f, 0)));
    app.world.addRigidBody(&body);
  }
  ~Ground() { app.world.removeRigidBody(&body); }
  Ground(const Ground&) = delete;
  Ground& operator=(const Ground&) = delete;
};

/// A free sheet of width^2 nodes, 2 m square, 0.5 kg, at height `elevation` (no pins).
inline std::shared_ptr<const Net> free_sheet(int width, double elevation = 0.7) {
  NetSpec spec;
  spec.name = "sheet";
  spec.width = spec.height = width;
  spec.size_x = spec.size_z = 2.0;
  spec.elevation = elevation;
  spec.mass = 0.5;
  spec.pinned_corners = 0;
  return std::make_shared<const Net>(spec);
}

}  // namespace tcsb::testing
