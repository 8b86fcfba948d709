#include "scene/scene_world.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <LinearMath/btDefaultMotionState.h>

#include <algorithm>
#include <cmath>

#include "softbody/bullet_setup.h"
#include "softbody/tc_softbody.h"
#include "softbody/tc_softbody_solver.h"

namespace tcsb {

namespace {

btVector3 to_vector(const std::array<double, 3>& v) {
  return {static_cast<btScalar>(v[0]), static_cast<btScalar>(v[1]), static_cast<btScalar>(v[2])};
}

btSoftBody::eAeroModel::_ aero_model(AeroModel model) {
  using Bullet = btSoftBody::eAeroModel;
  switch (model) {
    case AeroModel::kVPoint: return Bullet::V_Point;
    case AeroModel::kVTwoSided: return Bullet::V_TwoSided;
    case AeroModel::kVTwoSidedLiftDrag: return Bullet::V_TwoSidedLiftDrag;
    case AeroModel::kVOneSided: return Bullet::V_OneSided;
    case AeroModel::kFTwoSided: return Bullet::F_TwoSided;
    case AeroModel::kFTwoSidedLiftDrag: return Bullet::F_TwoSidedLiftDrag;
    case AeroModel::kFOneSided: return Bullet::F_OneSided;
  }
  return Bullet::V_Point;
}

/// The rotation that turns +y into `normal` (unit length).
btQuaternion rotation_to(const btVector3& normal) {
  const btVector3 up(0, 1, 0);
  const btScalar c = up.dot(normal);
  if (c > btScalar(1 - 1e-6)) return btQuaternion::getIdentity();
  if (c < btScalar(-1 + 1e-6)) return {btVector3(1, 0, 0), SIMD_PI};
  return {up.cross(normal).normalized(), std::acos(c)};
}

/// Depth inside a collider of a point given in the collider's own frame, metres (<= 0: outside). A plane's frame is
/// its slab's, whose top face is the plane.
double depth_inside(const Collider& c, const btVector3& local) {
  switch (c.shape) {
    case ColliderShape::kSphere: return c.radius - static_cast<double>(local.length());
    case ColliderShape::kPlane: return kPlaneSlabHalfThickness - static_cast<double>(local.y());
    case ColliderShape::kBox: {
      double depth = c.half_extents[0] - std::abs(static_cast<double>(local.x()));  // the shallowest way out
      depth = std::min(depth, c.half_extents[1] - std::abs(static_cast<double>(local.y())));
      return std::min(depth, c.half_extents[2] - std::abs(static_cast<double>(local.z())));
    }
  }
  return 0;
}

}  // namespace

/// A collider as Bullet holds it: shape, motion state and rigid body (static and kinematic ones have mass 0).
struct SceneWorld::Rigid {
  Collider spec;
  std::unique_ptr<btCollisionShape> shape;
  std::unique_ptr<btDefaultMotionState> motion;
  std::unique_ptr<btRigidBody> body;
  btVector3 start;  // the shape's centre at time 0
};

SceneWorld::Attachment& SceneWorld::Attachment::operator=(Attachment&& other) noexcept {
  if (this != &other) {
    release();
    world_ = other.world_;
    body_ = other.body_;
    other.world_ = nullptr;
  }
  return *this;
}

void SceneWorld::Attachment::release() {
  if (world_ != nullptr) world_->detach(*body_);
  world_ = nullptr;
}

SceneWorld::SceneWorld(const WorldSettings& world, const SceneSettings& scene) : settings_(world), scene_(scene) {
  const btVector3 gravity(0, static_cast<btScalar>(-world.gravity), 0);
  if (!scene_.has_colliders()) {
    solo_info_ = std::make_unique<btSoftBodyWorldInfo>();
    info_ = solo_info_.get();
    info_->m_gravity = gravity;
    info_->m_broadphase = nullptr;  // stepped solo, outside any collision world (docs/design.md, "One step")
    info_->m_dispatcher = nullptr;
    if (scene_.wind) info_->air_density = static_cast<btScalar>(scene_.wind->air_density);
    return;
  }
  configuration_ = std::make_unique<btSoftBodyRigidBodyCollisionConfiguration>();
  dispatcher_ = std::make_unique<btCollisionDispatcher>(configuration_.get());
  broadphase_ = std::make_unique<btDbvtBroadphase>();
  solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
  soft_body_solver_ = std::make_unique<TcSoftBodySolver>();  // a TC-SB body's own solve (tc_softbody_solver.h)
  dynamics_ = std::make_unique<btSoftRigidDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                         configuration_.get(), soft_body_solver_.get());
  dynamics_->setGravity(gravity);
  // The world's own info, whose broadphase, dispatcher and sparse SDF the world's constructor set up: a body built
  // with an info of its own would find neither (a null broadphase, and an SDF that divides by zero at first contact).
  info_ = &dynamics_->getWorldInfo();
  info_->m_gravity = gravity;
  if (scene_.wind) info_->air_density = static_cast<btScalar>(scene_.wind->air_density);
  info_->m_sparsesdf.setDefaultVoxelsz(static_cast<btScalar>(scene_.sdf_voxel));
  info_->m_sparsesdf.Reset();  // takes the voxel size

  for (const Collider& c : scene_.colliders) {
    auto rigid = std::make_unique<Rigid>();
    rigid->spec = c;
    btTransform placement;
    placement.setIdentity();
    rigid->start = to_vector(c.position);
    switch (c.shape) {
      case ColliderShape::kSphere:
        rigid->shape = std::make_unique<btSphereShape>(static_cast<btScalar>(c.radius));
        break;
      case ColliderShape::kBox: rigid->shape = std::make_unique<btBoxShape>(to_vector(c.half_extents)); break;
      case ColliderShape::kPlane: {
        const btVector3 n = to_vector(c.normal);
        rigid->shape = std::make_unique<btBoxShape>(btVector3(static_cast<btScalar>(kPlaneSlabHalfWidth),
                                                              static_cast<btScalar>(kPlaneSlabHalfThickness),
                                                              static_cast<btScalar>(kPlaneSlabHalfWidth)));
        placement.setRotation(rotation_to(n));
        rigid->start -= n * static_cast<btScalar>(kPlaneSlabHalfThickness);
        break;
      }
    }
    placement.setOrigin(rigid->start);
    const bool dynamic = c.motion == ColliderMotion::kDynamic;
    const btScalar mass = dynamic ? static_cast<btScalar>(c.mass) : btScalar(0);
    btVector3 inertia(0, 0, 0);
    if (dynamic) rigid->shape->calculateLocalInertia(mass, inertia);
    rigid->motion = std::make_unique<btDefaultMotionState>(placement);
    rigid->body = std::make_unique<btRigidBody>(
        btRigidBody::btRigidBodyConstructionInfo(mass, rigid->motion.get(), rigid->shape.get(), inertia));
    rigid->body->setFriction(static_cast<btScalar>(c.friction));
    if (c.motion == ColliderMotion::kKinematic) {
      rigid->body->setCollisionFlags(rigid->body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
      rigid->body->setActivationState(DISABLE_DEACTIVATION);
    }
    if (dynamic) {
      rigid->body->setLinearVelocity(to_vector(c.velocity));
      rigid->body->setActivationState(DISABLE_DEACTIVATION);  // a ball resting in the cloth must not fall asleep
    }
    dynamics_->addRigidBody(rigid->body.get());
    rigids_.push_back(std::move(rigid));
  }
}

SceneWorld::~SceneWorld() {
  // Bodies still attached are the owner's to destroy; the world must not touch them after this.
  std::vector<btSoftBody*> attached;
  for (const Attached& a : bodies_) attached.push_back(a.body);
  for (btSoftBody* body : attached) detach(*body);
  if (dynamics_) {
    for (const auto& rigid : rigids_) dynamics_->removeRigidBody(rigid->body.get());
    dynamics_.reset();
  }
}

SceneWorld::Attachment SceneWorld::attach(btSoftBody& body) {
  if (const std::optional<Wind>& wind = scene_.wind) {
    body.m_cfg.aeromodel = aero_model(wind->model);
    body.m_cfg.kLF = static_cast<btScalar>(wind->lift);
    body.m_cfg.kDG = static_cast<btScalar>(wind->drag);
    body.setWindVelocity(to_vector(wind->velocity));
    // The aerodynamic model reads node areas and normals, which Bullet derives from faces: a TC-SB body keeps them
    // over its cut, any other body gets its grid cells' (a body attached again keeps the faces it has).
    if (auto* tc = dynamic_cast<TcSoftBody*>(&body))
      tc->enable_faces();
    else if (body.m_faces.size() == 0)
      append_cell_faces(body);
  }
  if (dynamics_) {
    body.getCollisionShape()->setMargin(static_cast<btScalar>(scene_.margin));
    body.m_cfg.kDF = static_cast<btScalar>(scene_.friction);
    body.m_cfg.collisions = scene_.rigid_contact ? btSoftBody::fCollision::SDF_RS : 0;
    dynamics_->addSoftBody(&body);
  }
  const bool stock = dynamic_cast<TcSoftBody*>(&body) == nullptr;
  bodies_.push_back({&body, stock && scene_.pin_path.moves() ? StockPins(body) : StockPins()});
  return {this, &body};
}

void SceneWorld::detach(btSoftBody& body) {
  const auto it = std::find_if(bodies_.begin(), bodies_.end(), [&](const Attached& a) { return a.body == &body; });
  if (it == bodies_.end()) return;
  bodies_.erase(it);
  if (dynamics_) dynamics_->removeSoftBody(&body);
}

void SceneWorld::move_kinematic_colliders(double time) {
  for (const auto& rigid : rigids_) {
    if (rigid->spec.motion != ColliderMotion::kKinematic) continue;
    btTransform t = rigid->body->getWorldTransform();
    const Collider& c = rigid->spec;
    if (c.path.empty()) {
      t.setOrigin(rigid->start + to_vector(c.velocity) * static_cast<btScalar>(time));
    } else {
      // The path's displacement from where the collider started (`position`, the path's value at time 0, as the
      // parser sets it): a plane's slab keeps its shift under the plane.
      const std::array<double, 3> at = value_at(c.path, time);
      t.setOrigin(rigid->start + to_vector({at[0] - c.position[0], at[1] - c.position[1], at[2] - c.position[2]}));
    }
    rigid->motion->setWorldTransform(t);  // Bullet reads it and derives the body's velocity (saveKinematicState)
  }
}

void SceneWorld::move_pins(double time, btScalar dt) {
  const btVector3 offset = to_vector(scene_.pin_path.offset_at(time));
  for (Attached& a : bodies_) {
    if (auto* tc = dynamic_cast<TcSoftBody*>(a.body))
      tc->move_pins(offset, dt);
    else
      a.pins.move(*a.body, offset, dt);
  }
}

void SceneWorld::step(btScalar dt) {
  ++steps_;
  // Where the pins are after this step: at steps_ x dt, as the kinematic colliders.
  if (scene_.pin_path.moves()) move_pins(static_cast<double>(steps_) * settings_.dt, dt);
  if (!dynamics_) {
    for (const Attached& a : bodies_) step_body(*a.body, dt);
    return;
  }
  move_kinematic_colliders(static_cast<double>(steps_) * settings_.dt);
  dynamics_->stepSimulation(dt, 0);  // 0 substeps: one internal step of exactly dt
  info_->m_sparsesdf.GarbageCollect();
}

double SceneWorld::penetration(const btVector3& x) const {
  double deepest = -1e300;
  for (const auto& rigid : rigids_)
    deepest = std::max(deepest, depth_inside(rigid->spec, rigid->body->getWorldTransform().invXform(x)));
  return deepest;
}

}  // namespace tcsb
