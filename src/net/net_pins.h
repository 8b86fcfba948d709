// Net pins: which grid nodes a NetSpec holds fixed (the union of its corners, edges and listed nodes), and how
// those pins carry over to a coarser grid over the same rectangle (the uniform grid of a budget). Pure data.
#pragma once

#include <cstdint>
#include <vector>

#include "../net/net_spec.h"

namespace tcsb {

/// One flag per grid node, row-major along x (Net's order): 1 where the spec pins the node.
std::vector<std::uint8_t> pinned_grid_nodes(const NetSpec& spec);

/// Whether the spec pins anything beyond its corners (an edge or a listed node).
inline bool pins_beyond_corners(const NetSpec& spec) { return spec.pinned_edges != 0 || !spec.pinned_nodes.empty(); }

/// "min_x", "max_x", "min_z", "max_z": a suite's name of one PinnedEdge bit.
const char* pinned_edge_name(PinnedEdge edge);

/// The pins of `fine` carried to `coarse`, a grid over the same rectangle: corners and edges stay corners and edges
/// (they are where they are on any grid), and each listed node goes to the coarse node nearest it, duplicates
/// dropped, in the order first reached. Returns `coarse` with its pin fields set.
NetSpec with_pins_of(const NetSpec& fine, NetSpec coarse);

}  // namespace tcsb
