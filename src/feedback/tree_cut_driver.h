// TreeCutDriver: runs the TC-SB bodies' operations inside a world the application steps itself, with
// btDynamicsWorld::stepSimulation (substeps included). The bodies then live in the application's
// btSoftRigidDynamicsWorld like any soft body — collisions, rigid bodies, anchors, the world's own soft-body solver —
// and the driver does at each internal step what the harness does around its own step (case/case_body.cpp): end
// the blends, begin the controller's operations, and after the step let the controller see the result.
//
// One driver per world, installed by its constructor and uninstalled by its destructor (RAII): at every internal
// step it drives every TcSoftBody in the world's soft-body array at that moment — bodies added after it, and
// bodies that were never handed to drive() (those only advance their blends: no controller, no cut changes). A body
// that has left the world (removeSoftBody) is not touched until it is added again; a body destroyed while the driver
// knows it tells the driver, which forgets it and takes it out of the world first (Bullet's world would otherwise
// keep its address). Declare the driver after the world and before the bodies it drives, or anywhere: it never
// outlives its knowledge of a body, but it must not outlive the world (Bullet has no way to tell it the world went).
//
// Misuse gets an exception, never a crash: a second driver on the same world, or a world that already has a
// pre-tick callback of the application's (std::logic_error, from the constructor); a body that was not built with
// this world's btSoftBodyWorldInfo (std::invalid_argument from drive(); std::logic_error from the pre-tick, before
// Bullet's first use of that info would crash in btSoftBody::updateBounds, if such a body was added to the world).
//
// Why the pre-tick callback: Bullet calls it at the start of every internal step, before the world predicts the
// soft bodies' motion, so operations happen at a step boundary as TC-SB requires. The post-tick callback would be
// the wrong place: btSoftRigidDynamicsWorld calls it before it solves the soft bodies (inside
// btDiscreteDynamicsWorld::internalSingleStepSimulation), so it would see the body half-stepped. The controller's
// after_step therefore runs at the next pre-tick, first, while the last step's contacts are still Bullet's.
#pragma once

#include <BulletDynamics/Dynamics/btDynamicsWorld.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <memory>
#include <optional>
#include <vector>

#include "../feedback/controller.h"
#include "../feedback/world_budget.h"
#include "../softbody/tc_softbody.h"

namespace tcsb {

class TreeCutDriver final : private TcSoftBody::LifetimeListener {
 public:
  /// How the driver runs at each internal step.
  enum class Install {
    kCallback,  ///< as the world's pre-tick callback (the world must have none)
    /// not at all by itself: an application with a pre-tick callback of its own calls pre_tick() from it, first
    kManual,
  };

  /// Installs the driver on `world`. Throws std::logic_error when the world already has a TreeCutDriver, or (with
  /// Install::kCallback) a pre-tick callback of another.
  explicit TreeCutDriver(btSoftRigidDynamicsWorld& world, Install install = Install::kCallback);
  /// Uninstalls the driver (the world's pre-tick callback is cleared if it is still the driver's) and lets go of
  /// its bodies.
  ~TreeCutDriver() override;
  TreeCutDriver(const TreeCutDriver&) = delete;
  TreeCutDriver& operator=(const TreeCutDriver&) = delete;

  /// Drives `body` with `controller` (null: only its blends advance; the cut never changes by itself), replacing the
  /// controller it had. The body need not be in the world yet: it is driven while it is. The controller must outlive
  /// its use (until the body is destroyed, drive() gives it another, or the driver goes). Throws
  /// std::invalid_argument when the body was built with a btSoftBodyWorldInfo other than this world's
  /// getWorldInfo(), or when it is driven by another TreeCutDriver.
  void drive(TcSoftBody& body, Controller* controller);
  /// The same, the driver owning the controller.
  void drive(TcSoftBody& body, std::unique_ptr<Controller> controller);
  /// Forgets `body` (nothing if unknown): its controller sees its last step, pauses, and is not called again. While the
  /// body stays in the world it is still driven, as an unknown body is, without a controller.
  void release(TcSoftBody& body);

  /// The controller driving `body`, or null. Through it a running application changes the body's budget and camera
  /// (Controller::set_budget, set_spectator), effective at the next evaluation.
  Controller* controller(const TcSoftBody& body) const;
  /// controller(body)->set_budget(nodes) and set_spectator(spectator): effective at the body's next step boundary.
  /// Throw std::invalid_argument when the driver has no controller for the body (and what the controller throws).
  void set_budget(const TcSoftBody& body, int nodes);
  void set_spectator(const TcSoftBody& body, const Spectator& spectator);
  /// One node budget for all the bodies the driver has a controller for (feedback/world_budget.h: spent where their
  /// controllers rank detail highest, the bodies' shares re-split before every internal step, each body's
  /// controller then holding its share as its budget); std::nullopt, the default: each body keeps the budget its
  /// controller has. `hysteresis`: how much a block's priority must beat another body's to take its nodes (as
  /// FeedbackSettings::threshold within a body). Throws std::invalid_argument when nodes < 1.
  void set_world_budget(std::optional<int> nodes, double hysteresis = 0.05);

  /// What the callback does before every internal step, for every TC-SB body in the world: the controller sees the
  /// last step (after_step), the blends move on and finished operations end (advance_blends), new operations begin
  /// (before_step), the faces follow the cut (refresh_faces). Throws std::logic_error when a soft body of the world
  /// was built with another btSoftBodyWorldInfo than the world's.
  void pre_tick();

  /// Internal steps driven so far.
  long long ticks() const { return ticks_; }
  /// Internal steps `body` has been driven through (0 when unknown).
  long long ticks(const TcSoftBody& body) const;
  btSoftRigidDynamicsWorld& world() const { return world_; }

 private:
  struct Entry {
    TcSoftBody* body = nullptr;
    Controller* controller = nullptr;
    std::unique_ptr<Controller> owned;
    long long ticks = 0;
    bool stepped = false;  // in the world at the last tick, so after_step has a step to see
    bool seen = false;     // in the world at this tick
  };
  static void callback(btDynamicsWorld* world, btScalar time_step);
  void body_destroyed(TcSoftBody& body) override;
  Entry* find(const TcSoftBody& body);
  const Entry* find(const TcSoftBody& body) const;
  Entry& adopt(TcSoftBody& body);
  void check_world_info(const btSoftBody& body, bool from_tick) const;
  /// Before the driver stops calling an entry's controller (the body left the world, is released or destroyed, or
  /// gets another controller): the controller sees the body's last step and pauses. O(1) besides the controller.
  void quiesce(Entry& e);

  btSoftRigidDynamicsWorld& world_;
  Install install_;
  std::vector<std::unique_ptr<Entry>> entries_;
  long long ticks_ = 0;
  std::optional<int> world_budget_;
  double world_hysteresis_ = 0.05;
  std::vector<Entry*> ticking_;             // this tick's bodies, in the world's order
  std::vector<WorldBudgetMember> members_;  // of them, those with a controller, for the world budget
};

}  // namespace tcsb
