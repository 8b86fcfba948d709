// drape_tcsb: a TreeCut cloth at a 30 % node budget dropped onto a rigid sphere in the application's own
// btSoftRigidDynamicsWorld, stepped with stepSimulation (two substeps a frame), with the library's drape preset. The
// world is built with tcsb::TcSoftBodySolver, which solves the cloth's hanging interfaces between levels; the cloth
// starts at its level-1 cut, near its budget. A TreeCutDriver runs the cut's operations from the world's pre-tick
// callback; contact is an animation feature, so the cloth keeps detail where it lies on the sphere; a CutListener
// counts the cut's changes, as an application that keeps a render mesh of the simulated nodes would rebuild it. Prints
// the simulated node count N, the operations blending I, the contacts and the cut's changes, checks the cut's
// invariants every frame and that the cloth rests on the sphere; exits non-zero otherwise. Built against the installed
// package (examples/CMakeLists.txt).
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <tcsb/tcsb.h>

#include <algorithm>
#include <cstdio>
#include <memory>

int main() {
  // The application's world: soft-rigid collisions need the soft-body collision configuration, and every soft body
  // must be built with the world's own btSoftBodyWorldInfo (its broadphase, dispatcher and sparse SDF).
  btSoftBodyRigidBodyCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  tcsb::TcSoftBodySolver cloth_solver;  // Bullet's default soft-body solver, plus TC-SB's interfaces between levels
  btSoftRigidDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration, &cloth_solver);
  world.setGravity(btVector3(0, -9.81f, 0));
  btSoftBodyWorldInfo& info = world.getWorldInfo();
  info.m_gravity = world.getGravity();
  info.m_sparsesdf.setDefaultVoxelsz(0.05f);  // resolve the 0.5 m sphere finer than Bullet's default 0.25 m
  info.m_sparsesdf.Reset();

  // A static sphere of 0.5 m radius at the origin.
  btSphereShape ball_shape(0.5f);
  btRigidBody ball(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &ball_shape));
  world.addRigidBody(&ball);

  // The library's recommended settings for a drape (tcsb::drape_preset(), suites/drape.json, docs/library.md): 16
  // position iterations, hanging interfaces between levels, masses that follow the cut, links in a plain body's
  // order, contact as an animation feature. The cut starts at level 1 (17 x 17 nodes), near its budget.
  tcsb::Preset preset = tcsb::drape_preset();
  preset.tcsb.start_level = 1;

  // A free 2 m sheet of 33 x 33 nodes, 20 cm above the sphere.
  tcsb::NetSpec spec;
  spec.width = spec.height = 33;
  spec.size_x = spec.size_z = 2.0;
  spec.elevation = 0.7;
  spec.mass = 0.5;
  spec.pinned_corners = 0;
  spec.lod_rest = preset.lod_rest;  // blocks resting on their first leaf, as masses that follow the cut need
  const auto net = std::make_shared<const tcsb::Net>(spec);
  tcsb::TcSoftBody cloth(info, net, preset.solver, preset.tcsb);
  cloth.getCollisionShape()->setMargin(0.01f);
  // Made with the world's info, the cloth collides with the world's rigid bodies (m_cfg.collisions = SDF_RS: contacts
  // through the node tree) from the start.
  world.addSoftBody(&cloth);

  // What an application that draws the simulated nodes hears of the cut: here it only counts.
  struct ChangeCounter : tcsb::CutListener {
    void cut_changed(tcsb::OpKind, tcsb::TreeId) override { ++changes; }
    long long changes = 0;
  } counter;
  cloth.set_cut_listener(&counter);

  // The controller holds 30 % of the nodes; contact makes a node salient (at least a tenth of the most salient
  // motion). The driver runs the operations.
  const int budget = static_cast<int>(0.3 * static_cast<double>(spec.node_count()));
  const auto controller = tcsb::make_controller(preset.feedback, budget, /*seed=*/1);
  tcsb::TreeCutDriver driver(world);  // one per world: installed here, uninstalled when it goes
  driver.drive(cloth, controller.get());

  bool ok = true;
  for (int frame = 1; frame <= 90; ++frame) {
    world.stepSimulation(1.0f / 30.0f, 2, 1.0f / 60.0f);  // two internal steps a frame: two boundaries
    const tcsb::Validation validation = cloth.validate();
    if (!validation.ok()) {
      std::printf("frame %d: %s\n", frame, validation.summary().c_str());
      ok = false;
      break;
    }
    if (frame % 15 == 0)
      std::printf("frame %3d  N %4d  I %3d  contacts %4d  cut changes %lld\n", frame, cloth.node_count(),
                  cloth.interpolations(), cloth.m_rcontacts.size(), counter.changes);
  }
  // The cloth rests on the sphere (radius 0.5 m): its highest node near the top, none sunk deeper than 10 cm (Bullet
  // holds a contact at the 1 cm margin; its sparse SDF and the link solve after the contacts let nodes a little in).
  double top = -1e9, deepest = -1e9;
  for (int i = 0; i < cloth.m_nodes.size(); ++i) {
    top = std::max(top, static_cast<double>(cloth.m_nodes[i].m_x.y()));
    deepest = std::max(deepest, 0.5 - static_cast<double>(cloth.m_nodes[i].m_x.length()));
  }
  const bool rests = top > 0.4 && deepest < 0.1;
  std::printf("budget %d of %lld nodes, %lld internal steps; highest node at y %.3f m, deepest %.3f m inside (%s); "
              "invariants %s\n",
              budget, spec.node_count(), driver.ticks(), top, std::max(deepest, 0.0),
              rests ? "on the sphere" : "NOT on the sphere", ok ? "hold" : "broken");
  world.removeSoftBody(&cloth);
  world.removeRigidBody(&ball);
  return ok && rests ? 0 : 1;
}
