// Grid resampling: exact for affine fields and at the corners, so a coarse body that is an affine map of the fine
// one compares as error-free, and any error the fidelity pass reports comes from the bodies, not the sampling.
#include "net/grid_resample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace tcsb {
namespace {

/// An affine field over a grid spanning [-4, 4]^2 (as the paper's 8 m nets): x' = A (x, z) + b, any direction.
std::vector<Eigen::Vector3d> affine_field(GridSize g) {
  std::vector<Eigen::Vector3d> f(g.count());
  for (int j = 0; j < g.height; ++j)
    for (int i = 0; i < g.width; ++i) {
      const double x = -4.0 + 8.0 * i / (g.width - 1), z = -4.0 + 8.0 * j / (g.height - 1);
      f[static_cast<std::size_t>(j * g.width + i)] =
          Eigen::Vector3d(1.1 * x + 0.2 * z + 0.5, 8.0 - 0.3 * x + 0.7 * z, -0.1 * x + 0.9 * z - 1.0);
    }
  return f;
}

TEST(GridResample, ReproducesAnAffineFieldExactlyBetweenAnyTwoGrids) {
  for (const auto& [from, to] : std::vector<std::pair<GridSize, GridSize>>{
           {{9, 9}, {33, 33}}, {{33, 33}, {9, 9}}, {{25, 17}, {81, 45}}, {{81, 81}, {44, 44}}}) {
    const std::vector<Eigen::Vector3d> src = affine_field(from), want = affine_field(to);
    std::vector<Eigen::Vector3d> dst(to.count());
    resample_bilinear(from, src, to, dst);
    for (std::size_t i = 0; i < dst.size(); ++i)
      ASSERT_LT((dst[i] - want[i]).norm(), 1e-12)
          << from.width << "x" << from.height << " -> " << to.width << "x" << to.height << " node " << i;
  }
}

TEST(GridResample, CornersMapToCornersBitForBit) {
  const GridSize from{45, 45}, to{26, 26};
  std::vector<Eigen::Vector3d> src(from.count());
  for (std::size_t i = 0; i < src.size(); ++i) src[i] = Eigen::Vector3d(0.1 * i, std::sin(0.3 * i), -0.7 * i);
  std::vector<Eigen::Vector3d> dst(to.count());
  resample_bilinear(from, src, to, dst);
  EXPECT_EQ(dst[0], src[0]);
  EXPECT_EQ(dst[static_cast<std::size_t>(to.width - 1)], src[static_cast<std::size_t>(from.width - 1)]);
  EXPECT_EQ(dst[to.count() - static_cast<std::size_t>(to.width)],
            src[from.count() - static_cast<std::size_t>(from.width)]);
  EXPECT_EQ(dst.back(), src.back());
}

TEST(GridResample, SameGridIsTheIdentityAndACurvedFieldIsNotReproducedByACoarseGrid) {
  const GridSize g{17, 17}, coarse{5, 5};
  std::vector<Eigen::Vector3d> curved(g.count());
  for (std::size_t i = 0; i < curved.size(); ++i) {
    const double x = static_cast<double>(i % 17), z = static_cast<double>(i / 17);
    curved[i] = Eigen::Vector3d(x, 0.05 * (x - 8) * (x - 8) + 0.05 * (z - 8) * (z - 8), z);
  }
  std::vector<Eigen::Vector3d> same(g.count()), down(coarse.count()), up(g.count());
  resample_bilinear(g, curved, g, same);
  for (std::size_t i = 0; i < same.size(); ++i) ASSERT_EQ(same[i], curved[i]) << i;
  resample_bilinear(g, curved, coarse, down);
  resample_bilinear(coarse, down, g, up);
  double worst = 0;
  for (std::size_t i = 0; i < up.size(); ++i) worst = std::max(worst, (up[i] - curved[i]).norm());
  EXPECT_GT(worst, 0.1);  // the round trip loses the curvature between coarse nodes: the check can fail
}

TEST(GridResample, RejectsMismatchedSizes) {
  std::vector<Eigen::Vector3d> a(9), b(16), small(1);
  EXPECT_THROW(resample_bilinear({3, 3}, a, {4, 4}, std::span<Eigen::Vector3d>(a)), std::invalid_argument);
  EXPECT_THROW(resample_bilinear({3, 4}, a, {4, 4}, b), std::invalid_argument);
  EXPECT_THROW(resample_bilinear({1, 1}, small, {4, 4}, b), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
