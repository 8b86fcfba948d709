#include "suite/scene_block.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

namespace tcsb {

using namespace suite_fields;

namespace {

std::array<double, 3> read_vector(const Reader& r, const Object& o, const char* key, const NumberRange& range,
                                  std::array<double, 3> fallback) {
  const json* j = o.find(key);
  return j ? r.numbers<3>(*j, o.at(key), range) : fallback;
}

/// Keyframes of any scripted path are capped alike: a typo must not build a path of millions.
constexpr std::size_t kMaxKeyframes = 10000;

/// The array of keyframes at `at` (not empty, at most kMaxKeyframes): its size.
std::size_t keyframe_count(const Reader& r, const json& keys, const std::string& at) {
  r.array(keys, at);
  if (keys.size() > kMaxKeyframes)
    r.fail(at, "at most " + std::to_string(kMaxKeyframes) + " keyframes, got " + std::to_string(keys.size()));
  return keys.size();
}

/// A keyframe's "time": at least 0, and later than the keyframe before (`previous`, null for the first).
double parse_key_time(const Reader& r, const Object& key, const double* previous) {
  double time = 0;
  key.read("time", time, kNonNegative, true);
  if (previous && !(time > *previous))
    r.fail(key.at("time"), "must be later than the keyframe before (" + fmt_number(*previous) + ")");
  return time;
}

/// Keyframes of a scripted vector, [{"time": t, `value_key`: [x, y, z]}, ...], times strictly ascending.
std::vector<VectorKey> parse_vector_keys(const Reader& r, const json& keys, const std::string& at,
                                         const char* value_key) {
  std::vector<VectorKey> out;
  const std::size_t count = keyframe_count(r, keys, at);
  for (std::size_t i = 0; i < count; ++i) {
    const Object key(r, keys[i], index_path(at, i), {"time", value_key});
    VectorKey k;
    k.time = parse_key_time(r, key, out.empty() ? nullptr : &out.back().time);
    k.value = r.numbers<3>(key.need(value_key), key.at(value_key), kSceneCoordinate);
    out.push_back(k);
  }
  return out;
}

/// "pin_path": {"velocity": [x, y, z]} or {"keyframes": [{"time": t, "offset": [x, y, z]}, ...]}, exactly one.
PinPath parse_pin_path(const Reader& r, const json& j, const std::string& path) {
  const Object o(r, j, path, {"velocity", "keyframes"});
  if (j.size() != 1) r.fail(path, "must have exactly one of \"velocity\" or \"keyframes\", got " + j.dump());
  PinPath p;
  if (const json* v = o.find("velocity")) {
    p.velocity = r.numbers<3>(*v, o.at("velocity"), kSceneCoordinate);
    if (!p.moves()) r.fail(o.at("velocity"), "must not be zero (pins at rest need no path)");
    return p;
  }
  p.keyframes = parse_vector_keys(r, o.need("keyframes"), o.at("keyframes"), "offset");
  // The nets are built at rest: a first offset other than zero would jump every pin at the first step.
  if (p.keyframes.front().value != std::array<double, 3>{0, 0, 0})
    r.fail(index_path(o.at("keyframes"), 0) + ".offset", "must be [0, 0, 0]: the pins start at rest");
  return p;
}

Collider parse_collider(const Reader& r, const json& j, const std::string& path) {
  const Object o(r, j, path,
                 {"shape", "motion", "position", "radius", "half_extents", "normal", "velocity", "path", "mass",
                  "friction"});
  Collider c;
  c.shape = r.choice<ColliderShape>(
      o.need("shape"), o.at("shape"),
      {{"sphere", ColliderShape::kSphere}, {"box", ColliderShape::kBox}, {"plane", ColliderShape::kPlane}});
  o.read("motion", c.motion,
         {{"static", ColliderMotion::kStatic},
          {"kinematic", ColliderMotion::kKinematic},
          {"dynamic", ColliderMotion::kDynamic}});
  c.position = read_vector(r, o, "position", kSceneCoordinate, c.position);
  // Each shape takes its own size and nothing else's, so a misplaced key is an error, not silently ignored.
  const auto only_for = [&](const char* key, ColliderShape shape, const char* shape_name) {
    if (o.find(key) && c.shape != shape) r.fail(o.at(key), std::string("only for a ") + shape_name);
  };
  only_for("radius", ColliderShape::kSphere, "sphere");
  only_for("half_extents", ColliderShape::kBox, "box");
  only_for("normal", ColliderShape::kPlane, "plane");
  o.read("radius", c.radius, kSceneLength);
  c.half_extents = read_vector(r, o, "half_extents", kSceneLength, c.half_extents);
  if (const json* n = o.find("normal")) {
    std::array<double, 3> v = r.numbers<3>(*n, o.at("normal"), kSceneCoordinate);
    // Scaled by its largest component before its length is taken: a tiny normal's squares would underflow to 0.
    const double largest = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
    if (!(largest > 0)) r.fail(o.at("normal"), "must not be the zero vector");
    for (double& x : v) x /= largest;
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    c.normal = {v[0] / length, v[1] / length, v[2] / length};
  }
  if (c.shape == ColliderShape::kPlane && c.motion == ColliderMotion::kDynamic)
    r.fail(o.at("motion"), "a plane cannot be dynamic (it has no finite mass)");
  if (o.find("velocity") && c.motion == ColliderMotion::kStatic)
    r.fail(o.at("velocity"), "a static collider has no velocity");
  c.velocity = read_vector(r, o, "velocity", kSceneCoordinate, c.velocity);
  if (const json* keys = o.find("path")) {
    if (c.motion != ColliderMotion::kKinematic) r.fail(o.at("path"), "only for a kinematic collider");
    // The path gives every position; a velocity or a fixed position beside it would be silently ignored.
    for (const char* fixed : {"velocity", "position"})
      if (o.find(fixed)) r.fail(o.at(fixed), "not with a path (each keyframe gives its own position)");
    c.path = parse_vector_keys(r, *keys, o.at("path"), "position");
    c.position = value_at(c.path, 0);  // where it starts
  }
  if (o.find("mass") && c.motion != ColliderMotion::kDynamic) r.fail(o.at("mass"), "only for a dynamic collider");
  o.read("mass", c.mass, kSceneQuantity);
  o.read("friction", c.friction, kUnit);
  return c;
}

/// A camera pose's position and target (`o` holds both keys): distinct, and not looking along `up`.
CameraPose parse_camera_pose(const Reader& r, const Object& o, const std::array<double, 3>& up) {
  CameraPose pose;
  pose.position = r.numbers<3>(o.need("position"), o.at("position"), kSceneCoordinate);
  pose.target = r.numbers<3>(o.need("target"), o.at("target"), kSceneCoordinate);
  switch (camera_pose_problem(pose, up)) {
    case CameraPoseProblem::kNoDirection:
      r.fail(o.at("target"), "must differ from position (the camera must look somewhere)");
    case CameraPoseProblem::kLooksAlongUp:
      r.fail(o.at("target"), "the camera looks along its up direction, so the image has no up");
    case CameraPoseProblem::kNone: break;
  }
  return pose;
}

Camera parse_camera(const Reader& r, const json& j, const std::string& path) {
  const Object o(r, j, path, {"position", "target", "up", "fov_deg", "image", "path", "occlusion_cell_px"});
  Camera c;
  c.up = read_vector(r, o, "up", kSceneCoordinate, c.up);
  if (c.up == std::array<double, 3>{}) r.fail(o.at("up"), "must not be the zero vector");
  o.read("fov_deg", c.fov_deg, NumberRange{0.0, true, 180.0, true});
  if (const json* image = o.find("image")) {
    if (!image->is_array() || image->size() != 2)
      r.fail(o.at("image"), "must be [width, height] in pixels, got " + describe(*image));
    c.width_px = static_cast<int>(r.integer((*image)[0], index_path(o.at("image"), 0), 16, 16384));
    c.height_px = static_cast<int>(r.integer((*image)[1], index_path(o.at("image"), 1), 16, 16384));
  }
  // At most 64 pixels a cell: coarser, a silhouette's misjudged band would be most of a cloth far away.
  o.read("occlusion_cell_px", c.occlusion_cell_px, 1, Camera::kMaxOcclusionCellPx);
  if (const json* keys = o.find("path")) {
    // A path gives every pose; a fixed position or target beside it would be silently ignored.
    for (const char* fixed : {"position", "target"})
      if (o.find(fixed)) r.fail(o.at(fixed), "not with a path (each keyframe gives its own)");
    const std::size_t count = keyframe_count(r, *keys, o.at("path"));
    for (std::size_t i = 0; i < count; ++i) {
      const Object key(r, (*keys)[i], index_path(o.at("path"), i), {"time", "position", "target"});
      CameraKey k;
      k.time = parse_key_time(r, key, c.path.empty() ? nullptr : &c.path.back().time);
      k.pose = parse_camera_pose(r, key, c.up);
      c.path.push_back(k);
    }
    // Every pose between two keyframes must give an image too: one that looks along up (a crane shot passing over
    // its target) would stop the run at that step, so it is refused here, naming the keyframe it leads to.
    if (const std::optional<CameraPathProblem> bad = camera_path_problem(c.path, c.up)) {
      const CameraPose& a = c.path[bad->segment].pose;
      const CameraPose& b = c.path[bad->segment + 1].pose;
      const auto point = [](const std::array<double, 3>& v) {
        std::string text = "[";  // (appended piece by piece: GCC 12 -Wrestrict false positive on "[" + ...)
        text += fmt_number(v[0]) + ", " + fmt_number(v[1]) + ", " + fmt_number(v[2]) + "]";
        return text;
      };
      r.fail(index_path(o.at("path"), bad->segment + 1),
             "on the way from the keyframe before, at time " + fmt_number(bad->time) + " s (position " +
                 point(lerp(a.position, b.position, bad->weight)) + ", target " +
                 point(lerp(a.target, b.target, bad->weight)) + "), " +
                 (bad->problem == CameraPoseProblem::kNoDirection
                      ? std::string("the position meets the target, so the camera looks nowhere")
                      : std::string("the camera looks along its up direction, so the image has no up")) +
                 "; add a keyframe that steers around it");
    }
  } else {
    c.pose = parse_camera_pose(r, o, c.up);
  }
  return c;
}

Wind parse_wind(const Reader& r, const json& j, const std::string& path) {
  const Object o(r, j, path, {"model", "velocity", "lift", "drag", "air_density"});
  Wind w;
  o.read("model", w.model,
         {{"V_Point", AeroModel::kVPoint},
          {"V_TwoSided", AeroModel::kVTwoSided},
          {"V_TwoSidedLiftDrag", AeroModel::kVTwoSidedLiftDrag},
          {"V_OneSided", AeroModel::kVOneSided},
          {"F_TwoSided", AeroModel::kFTwoSided},
          {"F_TwoSidedLiftDrag", AeroModel::kFTwoSidedLiftDrag},
          {"F_OneSided", AeroModel::kFOneSided}});
  w.velocity = r.numbers<3>(o.need("velocity"), o.at("velocity"), kSceneCoordinate);
  o.read("lift", w.lift, kSceneNonNegative);
  o.read("drag", w.drag, kSceneNonNegative);
  // Bullet computes no aerodynamic force at all when both coefficients are 0 (btSoftBody::applyForces): a wind that
  // blows nothing would look like a scene with wind.
  if (!(w.lift > 0) && !(w.drag > 0))
    r.fail(path, "needs \"lift\" or \"drag\" above 0 (with both 0 Bullet applies no wind)");
  o.read("air_density", w.air_density, kSceneQuantity);
  return w;
}

/// `scene.collisions`: Bullet's fCollision names for the soft bodies. Only what a btSoftRigidDynamicsWorld can do
/// for a lone soft body of the harness is accepted; the rest are refused with the reason, not silently ignored.
bool parse_rigid_contact(const Reader& r, const json& j, const std::string& path) {
  r.array(j, path, EmptyArray::kAllowed);
  bool rigid_contact = false;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string at = index_path(path, i);
    const std::string flag = r.string(j[i], at);
    if (flag == "SDF_RS") {
      rigid_contact = true;
    } else if (flag == "CL_RS" || flag == "CL_SS" || flag == "CL_SELF") {
      r.fail(at, "\"" + flag +
                     "\" needs Bullet's clusters, which no body here has (TC-SB's changing node array "
                     "could not keep them)");
    } else if (flag == "VF_SS" || flag == "VF_DD") {
      r.fail(at, "\"" + flag + "\" collides two soft bodies, and every compared body has a world of its own");
    } else if (flag == "SDF_RD" || flag == "SDF_RDF" || flag == "SDF_MDF" || flag == "SDF_RDN") {
      r.fail(at, "\"" + flag + "\" is for btDeformableMultiBodyDynamicsWorld's solver, not btSoftRigidDynamicsWorld's");
    } else {
      r.fail(at, "expected \"SDF_RS\" (contact with the colliders; an empty list for none), got " + describe(j[i]));
    }
  }
  return rigid_contact;
}

/// `scene.bodies`: [{"net": NAME, "position": [x, y, z]}, ...], at least one. The names are checked against the
/// suite's nets where both are known (suite.cpp).
std::vector<SceneBody> parse_scene_bodies(const Reader& r, const json& j, const std::string& path) {
  r.array(j, path);
  // Every body is simulated by every method of the world pass: a cap keeps a typo from building thousands.
  constexpr std::size_t kMaxSceneBodies = 256;
  if (j.size() > kMaxSceneBodies)
    r.fail(path, "at most " + std::to_string(kMaxSceneBodies) + " bodies, got " + std::to_string(j.size()));
  std::vector<SceneBody> bodies;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string at = index_path(path, i);
    const Object o(r, j[i], at, {"net", "position"});
    SceneBody body;
    body.net = r.string(o.need("net"), o.at("net"));
    body.position = r.numbers<3>(o.need("position"), o.at("position"), kSceneCoordinate);
    bodies.push_back(std::move(body));
  }
  return bodies;
}

}  // namespace

SceneSettings parse_scene(const Reader& r, const json& j) {
  const Object o(r, j, "scene",
                 {"colliders", "margin", "friction", "sdf_voxel", "collisions", "camera", "wind", "pin_path",
                  "bodies"});
  SceneSettings scene;
  if (const json* colliders = o.find("colliders")) {
    r.array(*colliders, o.at("colliders"), EmptyArray::kAllowed);
    // Each collider is a rigid body in every case's world: a cap keeps a typo from building millions of them.
    constexpr std::size_t kMaxColliders = 64;
    if (colliders->size() > kMaxColliders)
      r.fail(o.at("colliders"),
             "at most " + std::to_string(kMaxColliders) + " colliders, got " + std::to_string(colliders->size()));
    for (std::size_t i = 0; i < colliders->size(); ++i)
      scene.colliders.push_back(parse_collider(r, (*colliders)[i], index_path(o.at("colliders"), i)));
  }
  o.read("margin", scene.margin, kSceneLength);
  o.read("friction", scene.friction, kUnit);
  // A voxel below a millimetre would make the SDF's cells (and their memory, clamped by Bullet) explode for nothing.
  o.read("sdf_voxel", scene.sdf_voxel, NumberRange{0.001, false, 10.0, false});
  if (const json* flags = o.find("collisions"))
    scene.rigid_contact = parse_rigid_contact(r, *flags, o.at("collisions"));
  if (const json* camera = o.find("camera")) scene.camera = parse_camera(r, *camera, o.at("camera"));
  if (const json* wind = o.find("wind")) scene.wind = parse_wind(r, *wind, o.at("wind"));
  if (const json* pins = o.find("pin_path")) scene.pin_path = parse_pin_path(r, *pins, o.at("pin_path"));
  if (const json* bodies = o.find("bodies")) scene.bodies = parse_scene_bodies(r, *bodies, o.at("bodies"));
  return scene;
}

}  // namespace tcsb
