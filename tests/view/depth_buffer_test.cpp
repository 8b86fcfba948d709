// The depth buffer: which points a camera sees, and which a surface in front of them hides.
#include "view/depth_buffer.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "test_camera.h"

namespace tcsb {
namespace {

// A square of side 2 x half_side in the plane z = `z`, facing the camera, as two triangles.
void add_square(DepthBuffer& buffer, const ScreenProjection& view, double half_side, double z) {
  const ScreenPoint a = view.project(Eigen::Vector3d(-half_side, -half_side, z));
  const ScreenPoint b = view.project(Eigen::Vector3d(half_side, -half_side, z));
  const ScreenPoint c = view.project(Eigen::Vector3d(half_side, half_side, z));
  const ScreenPoint d = view.project(Eigen::Vector3d(-half_side, half_side, z));
  buffer.add_triangle(a, b, c);
  buffer.add_triangle(a, c, d);
}

TEST(DepthBuffer, WithoutTrianglesEveryPointInViewIsVisible) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  const DepthBuffer buffer(view, 1);
  EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(0, 0, 0)), 0));
  EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(3, 1, -5)), 0));
  EXPECT_FALSE(buffer.visible(view.project(Eigen::Vector3d(0, 0, 20)), 0));  // behind the camera: not in view
}

TEST(DepthBuffer, ASurfaceInFrontHidesWhatIsBehindItAndNothingBeside) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  for (const int cell_px : {1, 4}) {
    DepthBuffer buffer(view, cell_px);
    add_square(buffer, view, 1.0, 5.0);  // five metres from the camera, 2 m wide: 20 pixels on the image
    EXPECT_FALSE(buffer.visible(view.project(Eigen::Vector3d(0, 0, 0)), 0.1)) << cell_px;
    EXPECT_FALSE(buffer.visible(view.project(Eigen::Vector3d(1.2, -0.8, -2)), 0.1)) << cell_px;  // in its shadow
    EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(4, 0, 0)), 0.1)) << cell_px;         // beside it
    EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(0, 0, 7)), 0.1)) << cell_px;         // in front of it
    EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(0.5, 0.5, 5)), 0.1)) << cell_px;     // on it
  }
}

TEST(DepthBuffer, ASurfaceBehindAPointHidesNothing) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  DepthBuffer buffer(view, 2);
  add_square(buffer, view, 3.0, -4.0);
  EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(0, 0, 0)), 0));
  EXPECT_FALSE(buffer.visible(view.project(Eigen::Vector3d(0, 0, -6)), 0.1));
}

TEST(DepthBuffer, TheToleranceDecidesBetweenALayerAndTheSurfaceItself) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  DepthBuffer buffer(view, 1);
  add_square(buffer, view, 1.0, 0.3);  // 0.3 m in front of the origin
  EXPECT_FALSE(buffer.visible(view.project(Eigen::Vector3d(0, 0, 0)), 0.1));
  EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(0, 0, 0)), 0.5));
}

TEST(DepthBuffer, InterpolatesDepthAlongTheLineOfSightNotAcrossTheImage) {
  // A plane tilted steeply away from the camera, z = -2 x. The ray through the centre of pixel (100, 50) meets it
  // 10 / 0.98 metres from the camera; depth interpolated linearly across the image would put it at 11.77 metres,
  // and a point a metre behind the plane would look in front of it.
  const ScreenProjection view(camera_looking_at_origin(), 0);
  DepthBuffer buffer(view, 1);
  const auto on_plane = [&](double x, double y) { return view.project(Eigen::Vector3d(x, y, -2 * x)); };
  buffer.add_triangle(on_plane(-2, -2), on_plane(2, -2), on_plane(2, 2));
  buffer.add_triangle(on_plane(-2, -2), on_plane(2, 2), on_plane(-2, 2));
  const auto on_ray = [&](double depth) {  // through the pixel's centre: 0.5 / 50 sideways a metre of depth
    return view.project(Eigen::Vector3d(0.01 * depth, -0.01 * depth, 10 - depth));
  };
  const double hit = 10 / 0.98;
  EXPECT_TRUE(buffer.visible(on_ray(hit - 0.01), 0.0));
  EXPECT_FALSE(buffer.visible(on_ray(hit + 0.01), 0.0));
  EXPECT_FALSE(buffer.visible(on_ray(hit + 1.0), 0.0));
}

TEST(DepthBuffer, ATriangleReachingBehindTheNearPlaneHidesNothing) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  DepthBuffer buffer(view, 1);
  buffer.add_triangle(view.project(Eigen::Vector3d(-1, -1, 5)), view.project(Eigen::Vector3d(1, -1, 5)),
                      view.project(Eigen::Vector3d(0, 1, 12)));
  EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(0, -0.5, 0)), 0));
}

TEST(DepthBuffer, ClearForgetsTheTriangles) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  DepthBuffer buffer(view, 1);
  add_square(buffer, view, 1.0, 5.0);
  buffer.clear();
  EXPECT_TRUE(buffer.visible(view.project(Eigen::Vector3d(0, 0, 0)), 0));
}

// clear() resets only the cells the triangles since the last clear may have touched: after squares in several
// places and clears in between, every cell must read as in a buffer that only ever saw the last square.
TEST(DepthBuffer, AfterClearsEveryCellReadsAsInAFreshBuffer) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  for (const int cell_px : {1, 3}) {
    DepthBuffer reused(view, cell_px);
    add_square(reused, view, 3.0, 2.0);  // near the lens: most of the image
    reused.clear();
    add_square(reused, view, 0.5, 3.0);
    add_square(reused, view, 1.0, -4.0);
    reused.clear();
    reused.clear();  // a clear with nothing drawn since
    add_square(reused, view, 1.0, 5.0);
    DepthBuffer fresh(view, cell_px);
    add_square(fresh, view, 1.0, 5.0);
    int hidden = 0;
    for (int j = 0; j < reused.rows(); ++j)
      for (int i = 0; i < reused.columns(); ++i) {
        ScreenPoint p;
        p.x = (i + 0.5) * cell_px;
        p.y = (j + 0.5) * cell_px;
        p.depth = 9.0;  // behind every square but the one at z = -4: a stale cell would hide it
        p.in_view = true;
        ASSERT_EQ(reused.visible(p, 0), fresh.visible(p, 0)) << cell_px << " cell " << i << ", " << j;
        hidden += reused.visible(p, 0) ? 0 : 1;
      }
    EXPECT_GT(hidden, 0) << cell_px;  // the last square is there
  }
}

TEST(DepthBuffer, CellsCoverTheWholeImage) {
  const ScreenProjection view(camera_looking_at_origin(), 0);  // 200 x 100 pixels
  const DepthBuffer fine(view, 1), coarse(view, 3);
  EXPECT_EQ(fine.columns(), 200);
  EXPECT_EQ(fine.rows(), 100);
  EXPECT_EQ(coarse.columns(), 67);
  EXPECT_EQ(coarse.rows(), 34);
  EXPECT_THROW(DepthBuffer(view, 0), std::invalid_argument);
}

// A cloth of w x h points folded over itself: rows [0, h/2) at z = 0, rows [h/2, h) in the same place one metre
// further from the camera, in reverse order, as if the lower half were folded back behind the upper.
std::vector<Eigen::Vector3d> folded_grid(int w, int h) {
  std::vector<Eigen::Vector3d> x;
  for (int y = 0; y < h; ++y)
    for (int i = 0; i < w; ++i) {
      const bool back = y >= h / 2;
      const int row = back ? h - 1 - y : y;
      x.emplace_back(-2.0 + 4.0 * i / (w - 1), -2.0 + 4.0 * row / (h / 2 - 1), back ? -1.0 : 0.0);
    }
  return x;
}

TEST(VisibleGridPoints, AFoldedClothShowsItsFrontLayerAndHidesTheBack) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  DepthBuffer buffer(view, 2);
  const int w = 9, h = 18;
  std::vector<std::uint8_t> visible;
  visible_grid_points(view, folded_grid(w, h), w, h, 0.25, buffer, visible);
  ASSERT_EQ(visible.size(), static_cast<std::size_t>(w * h));
  for (int y = 0; y < h; ++y)
    for (int i = 0; i < w; ++i) {
      const bool back = y >= h / 2;
      const bool rim = i == 0 || i == w - 1 || y == 0 || y == h - 1 || y == h / 2 - 1 || y == h / 2;
      if (!back) {
        EXPECT_EQ(visible[y * w + i], 1) << i << ", " << y;  // the front layer does not hide itself
      } else if (!rim) {
        EXPECT_EQ(visible[y * w + i], 0) << i << ", " << y;  // inside the front's outline: hidden
      }
    }
}

TEST(VisibleGridPoints, RefusesPointsThatAreNotTheGrid) {
  const ScreenProjection view(camera_looking_at_origin(), 0);
  DepthBuffer buffer(view, 1);
  std::vector<std::uint8_t> visible;
  EXPECT_THROW(visible_grid_points(view, folded_grid(3, 4), 3, 5, 0.1, buffer, visible), std::invalid_argument);
}

}  // namespace
}  // namespace tcsb
