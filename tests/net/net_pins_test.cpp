// Net pins: edges and listed nodes beside the corners, and how the pins carry over to a coarser grid.
#include "net/net_pins.h"

#include <gtest/gtest.h>

#include "net/net.h"

namespace tcsb {
namespace {

NetSpec spec_of(int w, int h) {
  NetSpec spec;
  spec.width = w;
  spec.height = h;
  spec.pinned_corners = 0;
  return spec;
}

TEST(NetPins, AnEdgePinsEveryNodeAlongItAndNothingElse) {
  for (const PinnedEdge edge : {kEdgeMinX, kEdgeMaxX, kEdgeMinZ, kEdgeMaxZ}) {
    NetSpec spec = spec_of(7, 5);
    spec.pinned_edges = edge;
    const Net net(spec);
    for (int z = 0; z < 5; ++z) {
      for (int x = 0; x < 7; ++x) {
        const bool on = (edge == kEdgeMinX && x == 0) || (edge == kEdgeMaxX && x == 6) ||
                        (edge == kEdgeMinZ && z == 0) || (edge == kEdgeMaxZ && z == 4);
        EXPECT_EQ(net.pinned()[static_cast<std::size_t>(net.index(x, z))] != 0, on)
            << pinned_edge_name(edge) << " node " << x << ", " << z;
      }
    }
  }
}

TEST(NetPins, ListedNodesAndCornersAreTheUnion) {
  NetSpec spec = spec_of(9, 9);
  spec.pinned_corners = kCornerMaxMax;
  spec.pinned_nodes = {{4, 4}, {0, 2}};
  const Net net(spec);
  int count = 0;
  for (const std::uint8_t p : net.pinned()) count += p;
  EXPECT_EQ(count, 3);
  EXPECT_TRUE(net.pinned()[static_cast<std::size_t>(net.index(8, 8))]);
  EXPECT_TRUE(net.pinned()[static_cast<std::size_t>(net.index(4, 4))]);
  EXPECT_TRUE(net.pinned()[static_cast<std::size_t>(net.index(0, 2))]);
  // A listed node off the grid is the parser's to refuse; the net refuses it too rather than write out of bounds.
  spec.pinned_nodes = {{9, 0}};
  EXPECT_THROW(Net{spec}, std::invalid_argument);
}

TEST(NetPins, CornerOnlySpecsPinExactlyTheirCorners) {
  // The form every suite had before edges and lists: the mask is the corners', so those nets are built as before.
  for (unsigned mask = 0; mask <= kAllCorners; ++mask) {
    NetSpec spec = spec_of(5, 3);
    spec.pinned_corners = mask;
    EXPECT_FALSE(pins_beyond_corners(spec));
    const std::vector<std::uint8_t> pinned = pinned_grid_nodes(spec);
    int count = 0;
    for (const std::uint8_t p : pinned) count += p;
    EXPECT_EQ(count, __builtin_popcount(mask));
    EXPECT_EQ(pinned[0] != 0, (mask & kCornerMinMin) != 0);
    EXPECT_EQ(pinned[4] != 0, (mask & kCornerMaxMin) != 0);
    EXPECT_EQ(pinned[10] != 0, (mask & kCornerMinMax) != 0);
    EXPECT_EQ(pinned[14] != 0, (mask & kCornerMaxMax) != 0);
  }
}

TEST(NetPins, ACoarserGridKeepsEdgesAndTakesTheNearestNodeOfEachListedOne) {
  NetSpec fine = spec_of(65, 65);
  fine.pinned_corners = kCornerMinMin;
  fine.pinned_edges = kEdgeMaxZ;
  fine.pinned_nodes = {{32, 32}, {33, 32}, {1, 63}};
  NetSpec coarse = fine;
  coarse.width = coarse.height = 5;  // node i of 5 at 16 i of 65
  coarse = with_pins_of(fine, coarse);
  EXPECT_EQ(coarse.pinned_corners, unsigned{kCornerMinMin});
  EXPECT_EQ(coarse.pinned_edges, unsigned{kEdgeMaxZ});
  // 32 and 33 both go to 2 (one pin, not two); 1 goes to 0 and 63 to 4.
  ASSERT_EQ(coarse.pinned_nodes.size(), 2u);
  EXPECT_EQ(coarse.pinned_nodes[0], (GridNode{2, 2}));
  EXPECT_EQ(coarse.pinned_nodes[1], (GridNode{0, 4}));
}

}  // namespace
}  // namespace tcsb
