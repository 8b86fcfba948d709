// SceneSettings: what surrounds the cloth, as a suite's optional "scene" block states it — rigid colliders and the
// soft body's contact settings. Plain data, validated by the suite parser; scene/scene_world.h builds the Bullet
// world from it. Without a scene block every field keeps its default, there are no colliders, and bodies are
// stepped solo exactly as before scenes existed (docs/design.md, "Scenes").
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "view/camera.h"
#include "view/keyframe_path.h"

namespace tcsb {

/// A collider's shape.
enum class ColliderShape {
  kSphere,  ///< radius around `position`
  kBox,     ///< axis-aligned half extents around `position`
  kPlane,   ///< the plane through `position` with unit normal `normal`; everything below it is inside
};

/// How a collider moves.
enum class ColliderMotion {
  kStatic,     ///< never moves
  kKinematic,  ///< moves along a scripted path, whatever the cloth does: `position` + `velocity` x t, or `path`
  kDynamic,    ///< a rigid body of `mass`, starting at `velocity`, pushed by gravity and the cloth
};

/// One rigid collider.
struct Collider {
  ColliderShape shape = ColliderShape::kSphere;
  ColliderMotion motion = ColliderMotion::kStatic;
  std::array<double, 3> position{0, 0, 0};      ///< centre (sphere, box) or a point on the plane, metres
  double radius = 1.0;                          ///< sphere, metres
  std::array<double, 3> half_extents{1, 1, 1};  ///< box, metres
  std::array<double, 3> normal{0, 1, 0};        ///< plane, unit length (the parser normalises it)
  std::array<double, 3> velocity{0, 0, 0};      ///< kinematic: constant; dynamic: initial; m/s
  /// Kinematic only, instead of a velocity: the centre's (or plane point's) positions at keyframe times
  /// (view/keyframe_path.h: linear between, held after the last); `position` is then the path's at time 0.
  /// Empty: `position` + `velocity` x t.
  std::vector<VectorKey> path;
  double mass = 1.0;      ///< dynamic only, kg
  double friction = 0.5;  ///< the rigid body's friction (Bullet combines it with the cloth's)
};

/// "static sphere", "dynamic box", "kinematic plane", "kinematic box on a path of 3 keyframes": how reports name a
/// collider.
std::string collider_name(const Collider& collider);

/// Bullet's aerodynamic models (btSoftBody::eAeroModel), as a suite names them. The V_ models push each node by its
/// own velocity against the wind, its normal and its area; the F_ models push each face. Both read the body's faces:
/// a body without faces has zero node areas and normals, and the wind does nothing to it.
enum class AeroModel {
  kVPoint,             ///< "V_Point"
  kVTwoSided,          ///< "V_TwoSided": the normal faces the relative wind, whichever side it comes from
  kVTwoSidedLiftDrag,  ///< "V_TwoSidedLiftDrag": drag along the relative wind, lift across it
  kVOneSided,          ///< "V_OneSided"
  kFTwoSided,          ///< "F_TwoSided"
  kFTwoSidedLiftDrag,  ///< "F_TwoSidedLiftDrag"
  kFOneSided,          ///< "F_OneSided"
};

/// A steady wind through the scene: Bullet's aerodynamic model of btSoftBody (its Config::aeromodel, kLF, kDG and
/// the body's wind velocity) with the world's air density. Bodies in a windy scene get faces (SceneWorld::attach).
struct Wind {
  AeroModel model = AeroModel::kVTwoSided;
  std::array<double, 3> velocity{0, 0, 0};  ///< the air's velocity, m/s
  double lift = 0.0;                        ///< kLF, lift coefficient, >= 0
  double drag = 0.0;                        ///< kDG, drag coefficient, >= 0
  double air_density = 1.2;                 ///< kg/m^3 (btSoftBodyWorldInfo::air_density; Bullet's default)
};

/// "V_TwoSided", ...: the suite's and Bullet's name of a model.
const char* aero_model_name(AeroModel model);

/// How every net's pins move: a scripted path of one offset from their rest positions, applied to every pinned node
/// alike (a rod holding the cloth, moved). Kinematic: whatever the cloth does, the pins follow the path.
struct PinPath {
  std::array<double, 3> velocity{0, 0, 0};  ///< a constant velocity, m/s (offset = velocity x t), when no keyframes
  std::vector<VectorKey> keyframes;         ///< else the offset's keyframes, metres (times ascending strictly)

  /// Whether the pins move at all (the default holds them at rest, as every scene before paths did).
  bool moves() const { return !keyframes.empty() || velocity != std::array<double, 3>{0, 0, 0}; }
  /// The pins' offset from rest at `time` seconds of simulated time, metres.
  std::array<double, 3> offset_at(double time) const {
    if (!keyframes.empty()) return value_at(keyframes, time);
    return {velocity[0] * time, velocity[1] * time, velocity[2] * time};
  }
};

/// A plane is built as a box (a slab) this thick under it and this wide (scene_world.cpp): Bullet's soft-rigid
/// contacts (the sparse SDF) measure distances to convex shapes only, and btStaticPlaneShape is not one. Here so
/// that the memory estimate (suite_memory.cpp) sizes the slab's distance field as the world builds it.
inline constexpr double kPlaneSlabHalfThickness = 0.5;
inline constexpr double kPlaneSlabHalfWidth = 100.0;

/// One body of a scene of many (docs/design.md, "Scenes of many bodies"): one of the suite's nets, standing where
/// `position` puts the centre of its rest rectangle ([centre x, elevation, centre z]), with the net's pins and mass.
struct SceneBody {
  std::string net;                          ///< the name of one of the suite's nets
  std::array<double, 3> position{0, 0, 0};  ///< metres
};

/// The scene around the nets.
struct SceneSettings {
  std::vector<Collider> colliders;
  /// The soft body's collision margin (btSoftBodyCollisionShape's), metres: a node closer than this to a collider's
  /// surface is in contact. Bullet's default, 0.25 m, is twice the grid spacing of the paper's 8 m net at 65 x 65;
  /// scenes state theirs.
  double margin = 0.02;
  /// The cloth's dynamic friction against rigid bodies (btSoftBody::Config::kDF), in [0, 1].
  double friction = 0.5;
  /// Edge of the sparse SDF's voxels, metres. Bullet finds soft-rigid contacts by interpolating each collider's
  /// distance field between samples this far apart (btSparseSdf), so a collider much smaller than a few voxels is
  /// blurred and nodes sink into it; Bullet's default is 0.25 m.
  double sdf_voxel = 0.25;
  /// The soft bodies' collision flags (btSoftBody::Config::collisions), as the suite's `collisions` lists them:
  /// contact with the colliders on their sparse SDF ("SDF_RS", Bullet's default and the only rigid-soft mode of a
  /// btSoftRigidDynamicsWorld without clusters), or none (an empty list: the cloth passes through the colliders,
  /// which still meet each other and the world). The other flags are refused where the suite is read (suite.cpp).
  bool rigid_contact = true;
  /// The spectator's camera: what the BSWDF's view terms (feedback.view) and the fidelity pass's error in pixels see
  /// through. None: no spectator, world-space errors only. It watches; it never changes the simulation.
  std::optional<Camera> camera;
  /// Wind, or none (still air: no body has faces, and no aerodynamic force is computed).
  std::optional<Wind> wind;
  /// How the nets' pins move; by default they stay at rest.
  PinPath pin_path;
  /// The cloths of a scene of many bodies, stepped in one world (the world pass); empty: each case's lone net.
  std::vector<SceneBody> bodies;

  /// Whether bodies live in a collision world (btSoftRigidDynamicsWorld) rather than being stepped solo.
  bool has_colliders() const { return !colliders.empty(); }
};

}  // namespace tcsb
