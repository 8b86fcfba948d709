// render_tcsb: the render path of a TreeCut cloth and what it costs. A drape (tcsb::drape_preset(), 30 % of the nodes)
// on a sphere in the application's world, stepped 120 frames of two internal steps, once without and once with what a
// renderer needs: enable_faces() (Bullet faces over the committed cut, and Bullet's node normals from them) and a
// CutListener that marks the index buffer stale, the buffer rebuilt from m_faces when it is and positions and normals
// copied every frame. Prints the median frame time of seven interleaved runs of each (the first 30 frames not
// counted) and the difference: docs/library.md, "Drawing the cut". A measuring program: no CTest runs it.
// Usage: render_tcsb [WIDTH]   (the sheet's nodes per side, default 65)
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <tcsb/tcsb.h>
#include <vector>
namespace {

/// What a renderer keeps of the cut: whether its index buffer is stale.
struct Mesh : tcsb::CutListener {
  bool dirty = true;
  void cut_changed(tcsb::OpKind, tcsb::TreeId) override { dirty = true; }
  void arrays_reordered() override { dirty = true; }
};
/// Mean frame time, ms, over frames 30-119, with or without the render path.
double run(bool render, int width) {
  btSoftBodyRigidBodyCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  tcsb::TcSoftBodySolver cloth_solver;
  btSoftRigidDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration, &cloth_solver);
  world.setGravity(btVector3(0, -9.81f, 0));
  world.getWorldInfo().m_gravity = world.getGravity();
  world.getWorldInfo().m_sparsesdf.setDefaultVoxelsz(0.05f);
  world.getWorldInfo().m_sparsesdf.Reset();
  btSphereShape ball_shape(0.5f);
  btRigidBody ball(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &ball_shape));
  world.addRigidBody(&ball);
  tcsb::Preset preset = tcsb::drape_preset();
  preset.tcsb.start_level = 1;
  tcsb::NetSpec spec;
  spec.width = spec.height = width;
  spec.size_x = spec.size_z = 2.0;
  spec.elevation = 0.7;
  spec.mass = 0.5;
  spec.pinned_corners = 0;
  spec.lod_rest = preset.lod_rest;
  auto net = std::make_shared<const tcsb::Net>(spec);
  tcsb::TcSoftBody cloth(world.getWorldInfo(), net, preset.solver, preset.tcsb);
  cloth.getCollisionShape()->setMargin(0.01f);
  Mesh mesh;
  std::vector<int> indices;
  std::vector<float> vertices;
  if (render) {
    cloth.enable_faces();
    cloth.set_cut_listener(&mesh);
  }
  world.addSoftBody(&cloth);
  tcsb::TreeCutDriver driver(world);
  driver.drive(cloth, tcsb::make_controller(preset.feedback, static_cast<int>(0.3 * spec.node_count()), 1));
  double total = 0;
  for (int frame = 0; frame < 120; ++frame) {
    const auto t0 = std::chrono::steady_clock::now();
    world.stepSimulation(1.0f / 30, 2, 1.0f / 60);
    if (render) {
      if (mesh.dirty) {  // the application's index buffer from Bullet's faces, rebuilt when the cut changed
        indices.clear();
        const btSoftBody::Node* base = &cloth.m_nodes[0];
        for (int f = 0; f < cloth.m_faces.size(); ++f)
          for (auto* n : cloth.m_faces[f].m_n) indices.push_back(static_cast<int>(n - base));
        mesh.dirty = false;
      }
      vertices.clear();  // positions and normals every frame
      for (int i = 0; i < cloth.m_nodes.size(); ++i)
        for (int k = 0; k < 3; ++k)
          vertices.push_back(cloth.m_nodes[i].m_x[k]), vertices.push_back(cloth.m_nodes[i].m_n[k]);
    }
    const auto t1 = std::chrono::steady_clock::now();
    if (frame >= 30) total += std::chrono::duration<double, std::milli>(t1 - t0).count();
  }
  world.removeSoftBody(&cloth);
  world.removeRigidBody(&ball);
  return total / 90;
}
}  // namespace

int main(int argc, char** argv) {
  const int width = argc > 1 ? std::atoi(argv[1]) : 65;
  std::vector<double> a, b;
  for (int r = 0; r < 7; ++r) {
    a.push_back(run(false, width));
    b.push_back(run(true, width));
  }
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::printf("width %d: ms/frame median without render path %.3f, with %.3f: +%.0f %%\n", width, a[3], b[3],
              100 * (b[3] / a[3] - 1));
}
