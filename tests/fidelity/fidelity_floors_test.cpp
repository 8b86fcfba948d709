// The fidelity floors' two instruments: the deterministic perturbation of a body's initial positions (the noise
// floor) and the resampling of a surface through a coarser rest grid (the interpolation floor).
#include "fidelity/fidelity_floors.h"

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/fidelity_metrics.h"
#include "fidelity/reconstruction.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"

namespace tcsb {
namespace {

Net small_net() {
  NetSpec spec;
  spec.width = spec.height = 9;
  return Net(spec);
}

std::vector<Eigen::Vector3d> positions(const btSoftBody& body) {
  std::vector<Eigen::Vector3d> x;
  copy_positions(body, x);
  return x;
}

TEST(PerturbPositions, ZeroAmplitudeLeavesTheBodyBitForBitAndSoItsTrajectory) {
  const Net net = small_net();
  SceneWorld world_a{WorldSettings{}}, world_b{WorldSettings{}};
  auto a = make_plain_softbody(world_a.info(), net, SolverSettings{});
  auto b = make_plain_softbody(world_b.info(), net, SolverSettings{});
  perturb_positions(*b, 0.0, 7);
  for (int s = 0; s < 50; ++s) {
    step_soft_body(*a, btScalar(1.0 / 60));
    step_soft_body(*b, btScalar(1.0 / 60));
  }
  // The noise floor with no perturbation: exactly 0, by the metric the pass uses.
  const SurfaceError e = surface_error(positions(*b), positions(*a));
  EXPECT_EQ(e.rms, 0.0);
  EXPECT_EQ(e.max, 0.0);
}

TEST(PerturbPositions, MovesEveryNodeWithinTheAmplitudeTheSameWayForTheSameSeed) {
  const Net net = small_net();
  SceneWorld world{WorldSettings{}};
  auto rest = make_plain_softbody(world.info(), net, SolverSettings{});
  auto a = make_plain_softbody(world.info(), net, SolverSettings{});
  auto b = make_plain_softbody(world.info(), net, SolverSettings{});
  auto c = make_plain_softbody(world.info(), net, SolverSettings{});
  const double amplitude = 1e-3;
  perturb_positions(*a, amplitude, 1);
  perturb_positions(*b, amplitude, 1);
  perturb_positions(*c, amplitude, 2);
  const std::vector<Eigen::Vector3d> x0 = positions(*rest), xa = positions(*a), xb = positions(*b), xc = positions(*c);
  int moved = 0;
  for (std::size_t i = 0; i < x0.size(); ++i) {
    const Eigen::Vector3d d = xa[i] - x0[i];
    EXPECT_LE(d.cwiseAbs().maxCoeff(), amplitude * (1 + 1e-3)) << i;  // float rounding of x + offset
    if (d.norm() > 0) ++moved;
    EXPECT_EQ(xa[i], xb[i]) << i;                                                              // deterministic
    EXPECT_EQ(a->m_nodes[static_cast<int>(i)].m_q, a->m_nodes[static_cast<int>(i)].m_x) << i;  // starts at rest
  }
  EXPECT_EQ(moved, static_cast<int>(x0.size()));
  EXPECT_GT(surface_error(xc, xa).rms, 0.0);  // another seed, other offsets
}

std::vector<Eigen::Vector3d> field(GridSize g, bool curved) {
  std::vector<Eigen::Vector3d> x(g.count());
  for (int j = 0; j < g.height; ++j)
    for (int i = 0; i < g.width; ++i) {
      const double u = i / double(g.width - 1), v = j / double(g.height - 1);
      x[static_cast<std::size_t>(j * g.width + i)] =
          Eigen::Vector3d(8 * u, curved ? -3 * std::sin(3.1 * u) * std::sin(2.3 * v) : 0.5 * u - 0.25 * v, 8 * v);
    }
  return x;
}

TEST(ResampleThrough, TheFullResolutionGridIsExact) {
  const GridSize fine{17, 13};
  const std::vector<Eigen::Vector3d> x = field(fine, true);
  std::vector<Eigen::Vector3d> scratch, out;
  resample_through(fine, x, fine, scratch, out);
  ASSERT_EQ(out.size(), x.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(out[i], x[i]) << i;  // bit for bit: floor 0
}

TEST(ResampleThrough, ACoarseGridLosesACurvedSurfaceButNotAnAffineOne) {
  const GridSize fine{17, 13};
  std::vector<Eigen::Vector3d> scratch, out;
  const std::vector<Eigen::Vector3d> flat = field(fine, false);
  resample_through(fine, flat, {6, 5}, scratch, out);
  EXPECT_LT(surface_error(out, flat).max, 1e-12);  // bilinear reproduces an affine field from any grid
  const std::vector<Eigen::Vector3d> curved = field(fine, true);
  resample_through(fine, curved, {9, 7}, scratch, out);
  const double fine_floor = surface_error(out, curved).rms;
  resample_through(fine, curved, {5, 4}, scratch, out);
  const double coarse_floor = surface_error(out, curved).rms;
  EXPECT_GT(fine_floor, 0.0);
  EXPECT_GT(coarse_floor, fine_floor);  // fewer nodes, more lost
}

}  // namespace
}  // namespace tcsb
