// Issue 23: a diverging case was reported at the step of the next full check (every kFullCheckEvery steps, or the
// run's last), so the same case "diverged at step 24, 44 or 49" depending on the run length. The runner replays a
// diverged repetition to find the first step after which the body fails a check.
#include <gtest/gtest.h>

#include "run/runner.h"
#include "softbody/divergence.h"

namespace tcsb {
namespace {

/// A 17 x 17 cloth, 2 m wide, with a time step (50 ms) too large for one solver iteration: a corner link stretches
/// beyond the sane bound (twice the net's size) after step 25 — a step no periodic full check looks at (they run
/// after steps 49, 99, ... and the last), so before the replay it was reported at 29, 49 and 49.
Suite diverging_suite(int steps, Method method) {
  Suite s;
  s.name = std::string("diverging");  // moved in: GCC 12 -Wrestrict false positive on literal assignment
  NetSpec n;
  n.width = n.height = 17;
  n.size_x = n.size_z = 2.0;
  n.elevation = 2.0;
  s.nets = {n};
  s.methods = {method};
  if (method == Method::kTcsb) s.compression = {1.0};
  s.world.dt = 0.05;
  s.world.gravity = 9.81;
  s.solver.piterations = 1;
  s.seed = 1;
  s.steps = steps;
  s.warmup_steps = 0;
  s.repetitions = 1;
  return s;
}

std::optional<int> diverged_step(const Suite& suite) {
  const RunResult run = run_suite(suite, Context{});
  const RepetitionResult& rep = run.cases.at(0).repetitions.at(0);
  if (rep.status != "diverged") return std::nullopt;
  return rep.diverged_step;
}

TEST(DivergenceStep, IndependentOfRunLength) {
  for (const Method method : {Method::kPlain, Method::kTcsb}) {
    const std::optional<int> at30 = diverged_step(diverging_suite(30, method));
    ASSERT_TRUE(at30) << method_name(method) << ": the setup no longer diverges within 30 steps";
    // Not a step the periodic check looks at: the replay, not the cadence, found it.
    EXPECT_NE((*at30 + 1) % kFullCheckEvery, 0) << method_name(method);
    EXPECT_NE(*at30, 29) << method_name(method) << ": found only by the check after the last step";
    EXPECT_EQ(diverged_step(diverging_suite(50, method)), at30) << method_name(method);
    EXPECT_EQ(diverged_step(diverging_suite(100, method)), at30) << method_name(method);
  }
}

TEST(DivergenceStep, LastFullCheckBefore) {
  EXPECT_EQ(last_full_check_before(0), -1);
  EXPECT_EQ(last_full_check_before(kFullCheckEvery - 1), -1);
  EXPECT_EQ(last_full_check_before(kFullCheckEvery), kFullCheckEvery - 1);
  EXPECT_EQ(last_full_check_before(3 * kFullCheckEvery + 7), 3 * kFullCheckEvery - 1);
}

}  // namespace
}  // namespace tcsb
