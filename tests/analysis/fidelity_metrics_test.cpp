// Fidelity metrics on hand-made surfaces whose answers are known in closed form.
#include "analysis/fidelity_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace tcsb {
namespace {

std::vector<Eigen::Vector3d> flat_grid(int w, double y) {
  std::vector<Eigen::Vector3d> g;
  for (int j = 0; j < w; ++j)
    for (int i = 0; i < w; ++i) g.emplace_back(i * 0.5, y, j * 0.5);
  return g;
}

TEST(SurfaceError, KnownDisplacementFieldGivesKnownRmsAndMax) {
  // Every other node moved by 3 cm along y, the rest by 4 cm along x: RMS = sqrt((9 + 16) / 2) cm, max 4 cm.
  const std::vector<Eigen::Vector3d> ref = flat_grid(10, 8.0);
  std::vector<Eigen::Vector3d> moved = ref;
  for (std::size_t i = 0; i < moved.size(); ++i)
    moved[i] += i % 2 ? Eigen::Vector3d(0, 0.03, 0) : Eigen::Vector3d(0.04, 0, 0);
  const SurfaceError e = surface_error(moved, ref);
  EXPECT_NEAR(e.rms, std::sqrt((0.03 * 0.03 + 0.04 * 0.04) / 2), 1e-15);
  EXPECT_NEAR(e.max, 0.04, 1e-15);
  EXPECT_EQ(e.weighted_rms, e.rms);
}

TEST(SurfaceError, IdenticalSurfacesHaveNoError) {
  const std::vector<Eigen::Vector3d> ref = flat_grid(7, 3.0);
  const SurfaceError e = surface_error(ref, ref, std::vector<float>(ref.size(), 0.5f));
  EXPECT_EQ(e.rms, 0.0);
  EXPECT_EQ(e.max, 0.0);
  EXPECT_EQ(e.weighted_rms, 0.0);
}

TEST(SurfaceError, UniformWeightsGiveTheRmsAndZeroWeightsFallBackToIt) {
  const std::vector<Eigen::Vector3d> ref = flat_grid(8, 1.0);
  std::vector<Eigen::Vector3d> moved = ref;
  for (std::size_t i = 0; i < moved.size(); ++i) moved[i].y() += 0.001 * static_cast<double>(i);
  const SurfaceError plain = surface_error(moved, ref);
  const SurfaceError uniform = surface_error(moved, ref, std::vector<float>(ref.size(), 0.37f));
  const SurfaceError zero = surface_error(moved, ref, std::vector<float>(ref.size(), 0.0f));
  EXPECT_NEAR(uniform.weighted_rms, plain.rms, 1e-12);
  EXPECT_EQ(zero.weighted_rms, plain.rms);  // nothing salient: every node counts the same
  EXPECT_EQ(uniform.rms, plain.rms);
}

TEST(SurfaceError, WeightsPickOutWhereTheErrorIsSeen) {
  const std::vector<Eigen::Vector3d> ref = flat_grid(4, 0.0);
  std::vector<Eigen::Vector3d> moved = ref;
  moved[5].y() += 0.2;  // one node wrong by 20 cm
  std::vector<float> on(ref.size(), 0.0f), off(ref.size(), 1.0f);
  on[5] = 1.0f;
  off[5] = 0.0f;
  EXPECT_NEAR(surface_error(moved, ref, on).weighted_rms, 0.2, 1e-12);  // all weight where the error is
  EXPECT_EQ(surface_error(moved, ref, off).weighted_rms, 0.0);          // no weight there
  EXPECT_NEAR(surface_error(moved, ref).rms, 0.2 / 4.0, 1e-12);         // sqrt(0.04 / 16)
}

TEST(SurfaceError, RejectsMismatchesAndBadWeights) {
  const std::vector<Eigen::Vector3d> a = flat_grid(3, 0), b = flat_grid(4, 0);
  EXPECT_THROW(surface_error(a, b), std::invalid_argument);
  EXPECT_THROW(surface_error(a, a, std::vector<float>(2, 1.0f)), std::invalid_argument);
  std::vector<float> w(a.size(), 1.0f);
  w[1] = -1.0f;
  EXPECT_THROW(surface_error(a, a, w), std::invalid_argument);
  w[1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(surface_error(a, a, w), std::invalid_argument);
}

TEST(MaxDisplacement, IsTheLargestJump) {
  const std::vector<Eigen::Vector3d> before = flat_grid(5, 2.0);
  std::vector<Eigen::Vector3d> after = before;
  EXPECT_EQ(max_displacement(before, after), 0.0);
  after[3] += Eigen::Vector3d(0.03, 0.04, 0);
  after[7] += Eigen::Vector3d(0.01, 0, 0);
  EXPECT_NEAR(max_displacement(before, after), 0.05, 1e-15);
  EXPECT_THROW(max_displacement(before, flat_grid(4, 2.0)), std::invalid_argument);
}

TEST(MechanicalEnergy, ABodyAtRestHasMgh) {
  const std::vector<Eigen::Vector3d> x = flat_grid(9, 8.0), v(x.size(), Eigen::Vector3d::Zero());
  const std::vector<double> m(x.size(), 1.0 / 81);
  EXPECT_NEAR(mechanical_energy(m, x, v, 9.81), 1.0 * 9.81 * 8.0, 1e-12);
}

TEST(MechanicalEnergy, AddsKineticEnergyAndCountsHeightFromZero) {
  const std::vector<Eigen::Vector3d> x{{0, -2.0, 0}, {1, 3.0, 0}}, v{{3, 4, 0}, {0, 0, 0}};
  const std::vector<double> m{2.0, 0.5};
  // 2 (25/2 + 10 * -2) + 0.5 (0 + 10 * 3)
  EXPECT_NEAR(mechanical_energy(m, x, v, 10.0), 2.0 * (12.5 - 20.0) + 0.5 * 30.0, 1e-12);
  EXPECT_THROW(mechanical_energy(std::vector<double>{1.0}, x, v, 10.0), std::invalid_argument);
}

TEST(EnergyDrift, IsTheDifferenceInPercentOfTheScale) {
  EXPECT_NEAR(energy_drift_pct(70.0, 72.0, 80.0), 2.5, 1e-12);
  EXPECT_NEAR(energy_drift_pct(74.0, 72.0, -80.0), 2.5, 1e-12);
  EXPECT_EQ(energy_drift_pct(5.0, 5.0, 80.0), 0.0);
  EXPECT_TRUE(std::isnan(energy_drift_pct(1.0, 0.0, 0.0)));  // undefined: left out by the caller
}

}  // namespace
}  // namespace tcsb
