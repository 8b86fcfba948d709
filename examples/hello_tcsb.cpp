// hello_tcsb: a TreeCut cloth at a 30 % node budget, stepped for two seconds, printing the simulated node count N
// and the operations blending I as it goes. Built against the installed package (examples/CMakeLists.txt).
#include <tcsb/tcsb.h>

#include <cstdio>
#include <memory>

int main() {
  // A 65 x 65 cloth, 8 m square, 1 kg, held at its four corners (the paper's nets, smallest size).
  tcsb::NetSpec spec;
  spec.width = spec.height = 65;
  const auto net = std::make_shared<const tcsb::Net>(spec);

  // The world parameters every body points at: gravity along -y and no collision world (the body is stepped solo),
  // and the solver as the paper suite states it.
  btSoftBodyWorldInfo world;
  world.m_gravity.setValue(0, -9.81f, 0);
  const btScalar dt = 1.0f / 60.0f;
  tcsb::SolverSettings solver;
  solver.piterations = 2;

  // The body starts at the finest cut (every grid node simulated); the controller brings it to the budget.
  tcsb::TcSoftBody body(world, net, solver, tcsb::TcSettings{});
  const int budget = static_cast<int>(0.3 * static_cast<double>(spec.node_count()));
  const auto controller = tcsb::make_controller(tcsb::FeedbackSettings{}, budget, /*seed=*/1);

  for (int step = 1; step <= 120; ++step) {
    body.advance_blends();          // blends move on; finished operations end
    controller->before_step(body);  // new operations begin, under the budget
    body.simulate_step(dt);         // one Bullet step
    controller->after_step(body);
    if (step % 20 == 0) std::printf("step %3d  N %5d  I %3d\n", step, body.node_count(), body.interpolations());
  }

  // The cut's invariants, checked once at the end (every broken one would be listed).
  const tcsb::Validation validation = body.validate();
  std::printf("budget %d of %lld nodes; invariants %s\n", budget, spec.node_count(),
              validation.ok() ? "hold" : validation.summary().c_str());
  return validation.ok() ? 0 : 1;
}
