// NetSpec: the parameters of one cloth net, as a suite names them. Plain data, validated by the suite parser.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace tcsb {

/// Which corners of the grid are pinned (held fixed). Bit values follow btSoftBodyHelpers::CreatePatch's `fixeds`.
enum PinnedCorner : unsigned {
  kCornerMinMin = 1,  ///< grid (0, 0)
  kCornerMaxMin = 2,  ///< grid (W-1, 0)
  kCornerMinMax = 4,  ///< grid (0, H-1)
  kCornerMaxMax = 8,  ///< grid (W-1, H-1)
  kAllCorners = 15,
};

/// Which edges of the grid are pinned, every node along them. Named like the corners, by the coordinate the edge
/// holds at its minimum or maximum: min_x is the edge x = 0 (from min_min to min_max).
enum PinnedEdge : unsigned {
  kEdgeMinX = 1,  ///< x = 0
  kEdgeMaxX = 2,  ///< x = W-1
  kEdgeMinZ = 4,  ///< z = 0
  kEdgeMaxZ = 8,  ///< z = H-1
};

/// One grid node by its coordinates: x in [0, W-1], z in [0, H-1].
struct GridNode {
  int x = 0;
  int z = 0;
  friend bool operator==(const GridNode&, const GridNode&) = default;
};

/// Where a block's node rests (LodTree::rest()). kCentroid: at its leaves' centroid, on the border along an axis
/// where the block touches one border. kVertex: on its first leaf (min x, min z), on the last leaf along an axis
/// where the block touches only the max border, so that every whole-level cut of a (2^k m + 1)-wide net is an evenly
/// spaced sub-grid of the leaves. Both rest a block holding one pinned leaf on that leaf.
enum class RestPlacement : std::uint8_t { kCentroid, kVertex };

/// How the net's mass is given: the whole net's, each node's (both spread evenly over the nodes), or an areal
/// density lumped by area (each node carries the density times its share of the cells around it: a quarter of each,
/// so border nodes carry half and corners a quarter of an inner node's; the compliant material's masses).
enum class MassMode { kTotal, kPerNode, kDensity };

/// One regular W x H cloth net lying flat in the x-z plane at height `elevation`, centred on (centre_x, centre_z),
/// gravity along -y.
struct NetSpec {
  std::string name = "net";  ///< label used in reports
  int width = 65;            ///< nodes along x (>= 2)
  int height = 65;           ///< nodes along z (>= 2)
  double size_x = 8.0;       ///< physical extent along x, metres
  double size_z = 8.0;       ///< physical extent along z, metres
  double elevation = 8.0;    ///< y of the rest plane, metres
  /// Where the rest rectangle's centre lies in x and z, metres: a scene of many bodies places each where it stands.
  double centre_x = 0.0;
  double centre_z = 0.0;
  MassMode mass_mode = MassMode::kTotal;
  double mass = 1.0;                      ///< total mass (kTotal) or per-node mass (kPerNode), kg; kg/m^2 (kDensity)
  unsigned pinned_corners = kAllCorners;  ///< PinnedCorner bits
  /// PinnedEdge bits. Pins are the union of the corners, the edges and the listed nodes (net/net_pins.h): corners
  /// alone are what every suite had before edges and lists existed, so those nets are built exactly as before.
  unsigned pinned_edges = 0;
  std::vector<GridNode> pinned_nodes;  ///< further pinned grid nodes, in the suite's order, no duplicates
  bool shear_links = false;            ///< add both diagonals of every grid cell
  bool bend_links = false;             ///< add links skipping one node along x and z
  /// Where the LOD tree's blocks rest (kVertex where a suite's TC-SB has masses that follow the cut, tcsb.masses).
  RestPlacement lod_rest = RestPlacement::kCentroid;

  /// The longer of the grid's two rest spacings (x and z), metres: one link's length at rest.
  double link_length() const { return std::max(size_x / std::max(1, width - 1), size_z / std::max(1, height - 1)); }
  /// Number of grid nodes (leaves of the LOD tree).
  long long node_count() const { return static_cast<long long>(width) * height; }
  /// Total mass of the net, kg.
  double total_mass() const {
    switch (mass_mode) {
      case MassMode::kTotal: return mass;
      case MassMode::kPerNode: return mass * static_cast<double>(node_count());
      case MassMode::kDensity: return mass * size_x * size_z;
    }
    return mass;
  }
  /// Mass of one grid node, kg: the mean over the nodes under kDensity (the nodes' masses differ there: Net).
  double node_mass() const {
    return mass_mode == MassMode::kPerNode ? mass : total_mass() / static_cast<double>(node_count());
  }
};

}  // namespace tcsb
