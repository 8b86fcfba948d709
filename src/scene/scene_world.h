// SceneWorld: the one place a body's Bullet world is built and stepped. Every method (plain, bullet_patch,
// plain_equal, TC-SB), the fidelity reference and its subjects, calibration and frames put their body into a
// SceneWorld and step it through step(), so whatever the scene costs, every compared body pays it alike.
//
// Without colliders a body is stepped solo — predictMotion, solveConstraints, integrateMotion, exactly what
// btSoftRigidDynamicsWorld does for a lone body with collisions off — and the world has no broadphase: the paper's
// scene, bit for bit as it ran before scenes existed. With colliders the body lives in a btSoftRigidDynamicsWorld
// with a broadphase, a dispatcher, Bullet's soft-rigid collision configuration and an initialised sparse SDF (an
// uninitialised one divides by zero at the first contact), and a step is stepSimulation(dt, 0): one internal step
// of dt, no interpolation.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <memory>
#include <vector>

#include "scene/scene_settings.h"
#include "softbody/pin_motion.h"
#include "softbody/solver_settings.h"

class btBroadphaseInterface;
class btCollisionConfiguration;
class btCollisionDispatcher;
class btConstraintSolver;
class btSoftBodySolver;
class btSoftRigidDynamicsWorld;

namespace tcsb {

class SceneWorld {
 public:
  /// A body's membership of the world: removes the body from it when destroyed. Declare it after the body it
  /// attaches, so it goes first (Bullet's world keeps the body's address until then).
  class Attachment {
   public:
    Attachment() = default;
    Attachment(SceneWorld* world, btSoftBody* body) : world_(world), body_(body) {}
    Attachment(Attachment&& other) noexcept : world_(other.world_), body_(other.body_) { other.world_ = nullptr; }
    Attachment& operator=(Attachment&& other) noexcept;
    Attachment(const Attachment&) = delete;
    Attachment& operator=(const Attachment&) = delete;
    ~Attachment() { release(); }
    /// Removes the body from the world now (nothing when already released).
    void release();

   private:
    SceneWorld* world_ = nullptr;
    btSoftBody* body_ = nullptr;
  };

  SceneWorld(const WorldSettings& world, const SceneSettings& scene = {});
  ~SceneWorld();
  SceneWorld(const SceneWorld&) = delete;
  SceneWorld& operator=(const SceneWorld&) = delete;

  /// What every soft body of this world must be built with (gravity, air density, broadphase, dispatcher, sparse
  /// SDF): bodies keep its address, so the world must outlive them.
  btSoftBodyWorldInfo& info() { return *info_; }
  const WorldSettings& settings() const { return settings_; }
  const SceneSettings& scene() const { return scene_; }
  /// Bullet's world when the scene has colliders (its rigid bodies are the colliders, in the scene's order), else
  /// null.
  btSoftRigidDynamicsWorld* dynamics() { return dynamics_.get(); }

  /// Puts a body built with info() into the world: with colliders, the scene's contact settings (margin,
  /// friction, soft-rigid collisions on) and the world's body list; stepped by every step() until released. When
  /// the scene's pins move, a stock body's pins are taken here, at their positions now (its rest).
  [[nodiscard]] Attachment attach(btSoftBody& body);
  /// One step of dt for every attached body (and, with colliders, the rigid bodies). First, when the scene's pins
  /// move, every body's pinned nodes are set on their way to the path's next offset (move_pins), so plain and TC-SB
  /// bodies are driven by the same rule in the same place.
  void step(btScalar dt);
  /// Steps taken so far.
  long long steps() const { return steps_; }

  /// How deep `x` lies inside the deepest collider, metres (<= 0: outside all of them), from the colliders' shapes
  /// where they are now. O(colliders).
  double penetration(const btVector3& x) const;
  /// Whether a node counts as having penetrated a collider: deeper than the contact margin. Bullet keeps nodes at
  /// the margin's distance; one deeper than that is where no contact held it.
  bool penetrated(double depth) const { return depth > scene_.margin; }

 private:
  struct Rigid;
  void detach(btSoftBody& body);
  void move_kinematic_colliders(double time);
  void move_pins(double time, btScalar dt);

  WorldSettings settings_;
  SceneSettings scene_;
  std::unique_ptr<btSoftBodyWorldInfo> solo_info_;  // without colliders
  btSoftBodyWorldInfo* info_ = nullptr;
  // With colliders: Bullet's world and what it is built from (the world is destroyed first: see the destructor).
  std::unique_ptr<btCollisionConfiguration> configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btConstraintSolver> solver_;
  std::unique_ptr<btSoftBodySolver> soft_body_solver_;
  std::unique_ptr<btSoftRigidDynamicsWorld> dynamics_;
  std::vector<std::unique_ptr<Rigid>> rigids_;  // one per collider, in the scene's order
  struct Attached {
    btSoftBody* body;
    StockPins pins;  // a stock body's, when the pins move (a TcSoftBody moves its own)
  };
  std::vector<Attached> bodies_;  // in attachment order
  long long steps_ = 0;
};

}  // namespace tcsb
