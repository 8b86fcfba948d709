// client_tcsb: what a game does with TC-SB, start to finish, in its own btSoftRigidDynamicsWorld stepped with
// stepSimulation: a cloth dropped on a sphere with one corner anchored to a rigid body that moves, a second cloth in
// the same world, one TreeCutDriver for both; mid-run the second cloth is removed from the world and destroyed, the
// first one's budget is lowered and raised, and the camera the feedback sees through orbits the scene all along
// (Controller::set_spectator every frame). Checks every frame that both cuts' invariants hold and the anchor holds;
// at the end that the cloth lies on the sphere and the budget was kept. Exits non-zero otherwise. Built against the
// installed package (examples/CMakeLists.txt; scripts/check-example.sh builds it against a library-only install).
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <tcsb/tcsb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr btScalar kStep = 1.0f / 60.0f;  // the world's internal step; two a frame

std::shared_ptr<const tcsb::Net> sheet(int width, double size, double elevation, tcsb::RestPlacement rest) {
  tcsb::NetSpec spec;
  spec.width = spec.height = width;
  spec.size_x = spec.size_z = size;
  spec.elevation = elevation;
  spec.mass = 0.5;
  spec.pinned_corners = 0;
  spec.lod_rest = rest;
  return std::make_shared<const tcsb::Net>(spec);
}

/// The camera on a circle of 3 m around the sphere, 1.5 m up, looking at it: `angle` radians around y.
tcsb::Spectator orbit(double angle) {
  tcsb::Spectator s;
  s.camera.pose = {{3 * std::cos(angle), 1.5, 3 * std::sin(angle)}, {0, 0.2, 0}};
  s.camera.fov_deg = 50;
  s.camera.width_px = 1280;
  s.camera.height_px = 720;
  s.dt = kStep;
  return s;
}

bool check(const tcsb::TcSoftBody& body, const char* name, int frame) {
  const tcsb::Validation v = body.validate();
  if (!v.ok()) std::printf("frame %d, %s: %s\n", frame, name, v.summary().c_str());
  return v.ok();
}

}  // namespace

int main() {
  btSoftBodyRigidBodyCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  tcsb::TcSoftBodySolver cloth_solver;
  btSoftRigidDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration, &cloth_solver);
  world.setGravity(btVector3(0, -9.81f, 0));
  btSoftBodyWorldInfo& info = world.getWorldInfo();
  info.m_gravity = world.getGravity();
  info.m_sparsesdf.setDefaultVoxelsz(0.05f);
  info.m_sparsesdf.Reset();

  // A static sphere of 0.5 m at the origin, and a 20 kg box (no gravity) that the game moves along a small circle.
  btSphereShape ball_shape(0.5f);
  btRigidBody ball(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &ball_shape));
  world.addRigidBody(&ball);
  btBoxShape box_shape(btVector3(0.04f, 0.04f, 0.04f));
  btVector3 inertia(0, 0, 0);
  box_shape.calculateLocalInertia(20, inertia);
  btRigidBody box(btRigidBody::btRigidBodyConstructionInfo(20, nullptr, &box_shape, inertia));
  box.setActivationState(DISABLE_DEACTIVATION);

  // The library's recommended drape (tcsb::drape_preset(), docs/library.md), the cut starting at level 1; made with
  // the world's info, so it collides with the sphere from the start.
  tcsb::Preset preset = tcsb::drape_preset();
  preset.tcsb.start_level = 1;
  const auto net = sheet(33, 2.0, 0.7, preset.lod_rest);
  auto cloth = std::make_unique<tcsb::TcSoftBody>(info, net, preset.solver, preset.tcsb);
  cloth->getCollisionShape()->setMargin(0.01f);
  // One corner held by the box: a node of the cut (start_level 1 keeps the corners' blocks at their corner leaves).
  const tcsb::TreeId corner_block = net->lod().at(1, 16, 16);
  const int corner = cloth->bullet_index(corner_block);
  if (corner < 0) {
    std::printf("the corner's block is not simulated\n");
    return 1;
  }
  const btVector3 corner_start = cloth->m_nodes[corner].m_x;
  box.setWorldTransform(btTransform(btQuaternion::getIdentity(), corner_start));
  world.addRigidBody(&box);
  box.setGravity(btVector3(0, 0, 0));  // after addRigidBody, which gives it the world's
  cloth->appendAnchor(corner, &box);
  world.addSoftBody(cloth.get());

  // A second cloth in the same world, 3 m away, falling freely: it leaves the world and is destroyed mid-run.
  auto other = std::make_unique<tcsb::TcSoftBody>(info, sheet(17, 1.0, 1.0, tcsb::RestPlacement::kCentroid),
                                                  preset.solver, tcsb::TcSettings{});
  other->translate(btVector3(3, 0, 0));
  world.addSoftBody(other.get());

  // One driver for the world; the draped cloth sees through the orbiting camera, the other by motion alone.
  tcsb::FeedbackSettings feedback = preset.feedback;
  feedback.view = true;  // and the camera's view terms (docs/library.md, "A close-up camera")
  int budget = static_cast<int>(0.3 * static_cast<double>(net->node_count()));
  tcsb::TreeCutDriver driver(world);
  driver.drive(*cloth, tcsb::make_controller(feedback, budget, 1, orbit(0)));
  driver.drive(*other, tcsb::make_controller(tcsb::FeedbackSettings{}, 120, 2));

  bool ok = true;
  double max_gap = 0;
  int over_budget_frames = 0;
  for (int frame = 1; frame <= 150 && ok; ++frame) {
    const double t = frame / 30.0;
    // The box circles its start, 15 cm across, at 0.3 m/s.
    box.setLinearVelocity(
        btVector3(static_cast<btScalar>(-0.3 * std::sin(2 * t)), 0, static_cast<btScalar>(0.3 * std::cos(2 * t))));
    box.setAngularVelocity(btVector3(0, 0, 0));
    driver.set_spectator(*cloth, orbit(2 * kPi * t / 5));  // a full orbit in 5 s
    if (frame == 50) {
      budget = static_cast<int>(0.2 * static_cast<double>(net->node_count()));  // the game needs time elsewhere
      driver.set_budget(*cloth, budget);
    }
    if (frame == 60) {
      world.removeSoftBody(other.get());
      other.reset();
    }
    if (frame == 100) {
      budget = static_cast<int>(0.4 * static_cast<double>(net->node_count()));
      driver.set_budget(*cloth, budget);
    }
    world.stepSimulation(2 * kStep, 2, kStep);
    ok = check(*cloth, "draped cloth", frame) && (!other || check(*other, "second cloth", frame));
    const btSoftBody::Anchor& a = cloth->m_anchors[0];
    max_gap =
        std::max(max_gap, static_cast<double>((a.m_node->m_x - a.m_body->getWorldTransform() * a.m_local).length()));
    if ((frame > 80 && frame < 100) || frame > 130) over_budget_frames += cloth->node_count() > budget;
  }
  double top = -1e9, deepest = -1e9;
  for (int i = 0; i < cloth->m_nodes.size(); ++i) {
    top = std::max(top, static_cast<double>(cloth->m_nodes[i].m_x.y()));
    deepest = std::max(deepest, 0.5 - static_cast<double>(cloth->m_nodes[i].m_x.length()));
  }
  const bool rests = top > 0.4 && deepest < 0.1;
  // Bullet's anchor is soft: the links solved after it pull the corner off its point (docs/library.md, "Anchors"), 6 cm
  // here at 16 iterations; an anchor that lost its node leaves the corner falling, metres away.
  const bool held = max_gap < 0.5;
  std::printf("client: %lld internal steps; N %d (budget %d, %d frames over it); anchor gap at most %.3f m (%s); "
              "highest node at y %.3f m, deepest %.3f m inside the sphere (%s); invariants %s\n",
              driver.ticks(), cloth->node_count(), budget, over_budget_frames, max_gap, held ? "held" : "NOT held", top,
              std::max(deepest, 0.0), rests ? "on the sphere" : "NOT on the sphere", ok ? "hold" : "broken");
  world.removeSoftBody(cloth.get());
  world.removeRigidBody(&box);
  world.removeRigidBody(&ball);
  return ok && rests && held && over_budget_frames == 0 ? 0 : 1;
}
