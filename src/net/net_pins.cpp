#include "net/net_pins.h"

#include <algorithm>
#include <cmath>

namespace tcsb {

std::vector<std::uint8_t> pinned_grid_nodes(const NetSpec& spec) {
  const int w = spec.width, h = spec.height;
  std::vector<std::uint8_t> pinned(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  const auto pin = [&](int x, int z) { pinned[static_cast<std::size_t>(z) * static_cast<std::size_t>(w) + x] = 1; };
  if (spec.pinned_corners & kCornerMinMin) pin(0, 0);
  if (spec.pinned_corners & kCornerMaxMin) pin(w - 1, 0);
  if (spec.pinned_corners & kCornerMinMax) pin(0, h - 1);
  if (spec.pinned_corners & kCornerMaxMax) pin(w - 1, h - 1);
  for (int z = 0; z < h; ++z) {
    if (spec.pinned_edges & kEdgeMinX) pin(0, z);
    if (spec.pinned_edges & kEdgeMaxX) pin(w - 1, z);
  }
  for (int x = 0; x < w; ++x) {
    if (spec.pinned_edges & kEdgeMinZ) pin(x, 0);
    if (spec.pinned_edges & kEdgeMaxZ) pin(x, h - 1);
  }
  for (const GridNode& n : spec.pinned_nodes) pin(n.x, n.z);
  return pinned;
}

const char* pinned_edge_name(PinnedEdge edge) {
  switch (edge) {
    case kEdgeMinX: return "min_x";
    case kEdgeMaxX: return "max_x";
    case kEdgeMinZ: return "min_z";
    case kEdgeMaxZ: return "max_z";
  }
  return "?";
}

NetSpec with_pins_of(const NetSpec& fine, NetSpec coarse) {
  coarse.pinned_corners = fine.pinned_corners;
  coarse.pinned_edges = fine.pinned_edges;
  coarse.pinned_nodes.clear();
  // Node i of a grid of n lies at i / (n-1) of the extent; the nearest coarse node is the rounded scaled index.
  const auto nearest = [](int i, int from, int to) {
    return static_cast<int>(std::lround(static_cast<double>(i) * (to - 1) / (from - 1)));
  };
  for (const GridNode& n : fine.pinned_nodes) {
    const GridNode c{nearest(n.x, fine.width, coarse.width), nearest(n.z, fine.height, coarse.height)};
    if (std::find(coarse.pinned_nodes.begin(), coarse.pinned_nodes.end(), c) == coarse.pinned_nodes.end())
      coarse.pinned_nodes.push_back(c);
  }
  return coarse;
}

}  // namespace tcsb
