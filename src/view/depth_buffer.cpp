#include "view/depth_buffer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tcsb {

namespace {
constexpr float kEmptyCell = std::numeric_limits<float>::infinity();
}  // namespace

DepthBuffer::DepthBuffer(const ScreenProjection& view, int cell_px) : cell_px_(cell_px) {
  if (cell_px < 1) throw std::invalid_argument("DepthBuffer: cell_px must be at least 1");
  columns_ = std::max(1, static_cast<int>(std::ceil(view.width_px() / cell_px)));
  rows_ = std::max(1, static_cast<int>(std::ceil(view.height_px() / cell_px)));
  nearest_.assign(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_), kEmptyCell);
}

void DepthBuffer::clear() {
  const auto columns = static_cast<std::size_t>(columns_);
  for (int j = dirty_j0_; j <= dirty_j1_; ++j) {
    const auto row = nearest_.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(j) * columns);
    std::fill(row + dirty_i0_, row + dirty_i1_ + 1, kEmptyCell);
  }
  dirty_i0_ = dirty_j0_ = 0;
  dirty_i1_ = dirty_j1_ = -1;
}

void DepthBuffer::add_triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c) {
  if (a.depth < kNearPlane || b.depth < kNearPlane || c.depth < kNearPlane) return;
  // Twice the signed area; a triangle seen edge-on covers no cell centre.
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (!(std::abs(area) > 0)) return;
  const double cell = cell_px_;
  // Cells whose centre (i + 0.5) x cell may lie inside the triangle's bounding box.
  const auto first = [cell](double lo) { return static_cast<int>(std::ceil(lo / cell - 0.5)); };
  const auto last = [cell](double hi) { return static_cast<int>(std::floor(hi / cell - 0.5)); };
  const int i0 = std::max(0, first(std::min({a.x, b.x, c.x})));
  const int i1 = std::min(columns_ - 1, last(std::max({a.x, b.x, c.x})));
  const int j0 = std::max(0, first(std::min({a.y, b.y, c.y})));
  const int j1 = std::min(rows_ - 1, last(std::max({a.y, b.y, c.y})));
  if (i0 > i1 || j0 > j1) return;
  if (dirty_i0_ > dirty_i1_) {
    dirty_i0_ = i0, dirty_i1_ = i1, dirty_j0_ = j0, dirty_j1_ = j1;
  } else {
    dirty_i0_ = std::min(dirty_i0_, i0), dirty_i1_ = std::max(dirty_i1_, i1);
    dirty_j0_ = std::min(dirty_j0_, j0), dirty_j1_ = std::max(dirty_j1_, j1);
  }
  const double inv_a = 1.0 / a.depth, inv_b = 1.0 / b.depth, inv_c = 1.0 / c.depth;
  for (int j = j0; j <= j1; ++j) {
    const double y = (j + 0.5) * cell;
    for (int i = i0; i <= i1; ++i) {
      const double x = (i + 0.5) * cell;
      // Barycentric weights by the edge functions, positive inside whichever way round the corners run.
      const double wa = ((b.x - x) * (c.y - y) - (b.y - y) * (c.x - x)) / area;
      const double wb = ((c.x - x) * (a.y - y) - (c.y - y) * (a.x - x)) / area;
      const double wc = 1.0 - wa - wb;
      if (wa < 0 || wb < 0 || wc < 0) continue;
      const float depth = static_cast<float>(1.0 / (wa * inv_a + wb * inv_b + wc * inv_c));
      float& nearest =
          nearest_[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(i)];
      nearest = std::min(nearest, depth);
    }
  }
}

bool DepthBuffer::visible(const ScreenPoint& p, double tolerance) const {
  if (!p.in_view) return false;
  // An image on the right or bottom edge belongs to the last cell.
  const int i = std::min(columns_ - 1, static_cast<int>(p.x / cell_px_));
  const int j = std::min(rows_ - 1, static_cast<int>(p.y / cell_px_));
  return p.depth <=
         static_cast<double>(
             nearest_[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(i)]) +
             tolerance;
}

void visible_grid_points(const ScreenProjection& view, std::span<const Eigen::Vector3d> points, int width, int height,
                         double tolerance, DepthBuffer& buffer, std::vector<std::uint8_t>& visible) {
  const std::size_t grid =
      width < 1 || height < 1 ? 0 : static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (grid == 0 || points.empty() || points.size() % grid != 0)
    throw std::invalid_argument("visible_grid_points: points do not form width x height grids");
  std::vector<ScreenPoint> image(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) image[k] = view.project(points[k]);
  buffer.clear();
  for (std::size_t first = 0; first < points.size(); first += grid) {
    const auto at = [first, width](int x, int y) {
      return first + static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x;
    };
    for (int y = 0; y + 1 < height; ++y)
      for (int x = 0; x + 1 < width; ++x) {
        buffer.add_triangle(image[at(x, y)], image[at(x + 1, y)], image[at(x + 1, y + 1)]);
        buffer.add_triangle(image[at(x, y)], image[at(x + 1, y + 1)], image[at(x, y + 1)]);
      }
  }
  visible.resize(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) visible[k] = buffer.visible(image[k], tolerance) ? 1 : 0;
}

}  // namespace tcsb
