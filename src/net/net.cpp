#include "net/net.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "net/net_pins.h"

namespace tcsb {

Net::Net(const NetSpec& spec, RestPlacement rest) : spec_(spec) {
  const int w = spec.width, h = spec.height;
  if (w < 2 || h < 2) throw std::invalid_argument("Net: width and height must be >= 2");
  if (!(spec.size_x > 0) || !(spec.size_z > 0) || !(spec.mass > 0))
    throw std::invalid_argument("Net: sizes and mass must be positive");
  // Issue 60: an infinite size, elevation or mass (or a NaN elevation) built a net of non-finite rest positions.
  for (const auto& [field, value] : {std::pair<const char*, double>{"size_x", spec.size_x},
                                     {"size_z", spec.size_z},
                                     {"elevation", spec.elevation},
                                     {"centre_x", spec.centre_x},
                                     {"centre_z", spec.centre_z},
                                     {"mass", spec.mass}})
    if (!std::isfinite(value)) throw std::invalid_argument(std::string("Net: ") + field + " must be finite");
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  rest_.resize(n);
  mass_.assign(n, spec.node_mass());
  if (spec.mass_mode == MassMode::kDensity) {
    // Lumped by area: a quarter of each cell the node is a corner of (1 inside, 1/2 on a border, 1/4 at a corner).
    const double cell = spec.mass * (spec.size_x / (w - 1)) * (spec.size_z / (h - 1));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        mass_[static_cast<std::size_t>(index(x, y))] =
            cell * (x == 0 || x == w - 1 ? 0.5 : 1.0) * (y == 0 || y == h - 1 ? 0.5 : 1.0);
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      rest_[static_cast<std::size_t>(index(x, y))] =
          Eigen::Vector3d(spec.centre_x - 0.5 * spec.size_x + spec.size_x * x / (w - 1), spec.elevation,
                          spec.centre_z - 0.5 * spec.size_z + spec.size_z * y / (h - 1));
  for (const GridNode& p : spec.pinned_nodes)
    if (p.x < 0 || p.x >= w || p.z < 0 || p.z >= h) throw std::invalid_argument("Net: a pinned node lies off the grid");
  pinned_ = pinned_grid_nodes(spec);

  links_.reserve(expected_link_count(spec));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const TreeId i = index(x, y);
      if (x + 1 < w) links_.push_back({i, index(x + 1, y), LinkKind::kStructural});
      if (y + 1 < h) links_.push_back({i, index(x, y + 1), LinkKind::kStructural});
      if (spec.shear_links && x + 1 < w && y + 1 < h) {
        links_.push_back({i, index(x + 1, y + 1), LinkKind::kShear});
        links_.push_back({index(x + 1, y), index(x, y + 1), LinkKind::kShear});
      }
      if (spec.bend_links) {
        if (x + 2 < w) links_.push_back({i, index(x + 2, y), LinkKind::kBend});
        if (y + 2 < h) links_.push_back({i, index(x, y + 2), LinkKind::kBend});
      }
    }
  }
  lod_ = std::make_unique<const LodTree>(w, h, rest_, mass_, pinned_, rest);
}

double Net::total_mass() const {
  double sum = 0;
  for (double m : mass_) sum += m;
  return sum;
}

std::size_t expected_link_count(const NetSpec& spec) {
  const std::size_t w = static_cast<std::size_t>(spec.width), h = static_cast<std::size_t>(spec.height);
  std::size_t count = w * (h - 1) + h * (w - 1);
  if (spec.shear_links) count += 2 * (w - 1) * (h - 1);
  if (spec.bend_links) count += (w > 2 ? (w - 2) * h : 0) + (h > 2 ? (h - 2) * w : 0);
  return count;
}

}  // namespace tcsb
