// TreeCutDriver: runs a TC-SB body's operations inside a world the application steps itself, with
// btDynamicsWorld::stepSimulation (substeps included). The body then lives in the application's
// btSoftRigidDynamicsWorld like any soft body — collisions, rigid bodies, the world's own soft-body solver — and the
// driver does at each internal step what the harness does around its own step (case/case_body.cpp): end the
// blends, begin the controller's operations, and after the step let the controller see the result.
//
// Why the pre-tick callback: Bullet calls it at the start of every internal step, before the world predicts the
// soft bodies' motion, so operations happen at a step boundary as TC-SB requires. The post-tick callback would be
// the wrong place: btSoftRigidDynamicsWorld calls it before it solves the soft bodies (inside
// btDiscreteDynamicsWorld::internalSingleStepSimulation), so it would see the body half-stepped. The controller's
// after_step therefore runs at the next pre-tick, first, while the last step's contacts are still Bullet's.
#pragma once

#include <BulletDynamics/Dynamics/btDynamicsWorld.h>

#include "../feedback/controller.h"
#include "../softbody/tc_softbody.h"

namespace tcsb {

class TreeCutDriver {
 public:
  /// Drives `body` with `controller` (null: only the blends advance, the cut never changes by itself). Both must
  /// outlive the driver's use.
  TreeCutDriver(TcSoftBody& body, Controller* controller) : body_(body), controller_(controller) {}

  /// Makes this driver the world's pre-tick callback (replacing any other, and the world's user info pointer). An
  /// application with a pre-tick callback of its own calls pre_tick() from it instead. The driver must outlive the
  /// world's stepping, or be uninstalled with world.setInternalTickCallback(nullptr, nullptr, true).
  void install(btDynamicsWorld& world) { world.setInternalTickCallback(&TreeCutDriver::callback, this, true); }

  /// What the callback does before every internal step: the controller sees the last step (after_step), the blends
  /// move on and finished operations end (advance_blends), new operations begin (before_step).
  void pre_tick();

  /// Internal steps driven so far.
  long long ticks() const { return ticks_; }

 private:
  static void callback(btDynamicsWorld* world, btScalar time_step);

  TcSoftBody& body_;
  Controller* controller_;
  long long ticks_ = 0;
};

}  // namespace tcsb
