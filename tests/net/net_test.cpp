// Net: node and link counts, canonical link order, rest positions, masses and pinned corners.
#include "net/net.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace tcsb {
namespace {

struct NetSize {
  int w, h;
};
// Square and not, powers of two (plus one) and not, the smallest net and thin ones.
const std::vector<NetSize> kNetSizes = {{2, 2}, {3, 7}, {7, 3}, {2, 9}, {17, 9}, {33, 17}, {65, 65}};

NetSpec net_spec(int w, int h, bool shear = false, bool bend = false) {
  NetSpec spec;
  spec.width = w;
  spec.height = h;
  spec.shear_links = shear;
  spec.bend_links = bend;
  return spec;
}

std::string label(const NetSpec& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height) + (s.shear_links ? " +shear" : "") +
         (s.bend_links ? " +bend" : "");
}

// Closed forms, written independently of expected_link_count.
std::size_t structural_formula(long long w, long long h) { return static_cast<std::size_t>(2 * w * h - w - h); }
std::size_t shear_formula(long long w, long long h) { return static_cast<std::size_t>(2 * (w - 1) * (h - 1)); }
std::size_t bend_formula(long long w, long long h) {
  return static_cast<std::size_t>(std::max(0LL, w - 2) * h + std::max(0LL, h - 2) * w);
}

TEST(Net, NodeCountIsWidthTimesHeight) {
  for (const NetSize s : kNetSizes) {
    const NetSpec spec = net_spec(s.w, s.h);
    const Net net(spec);
    EXPECT_EQ(net.node_count(), static_cast<std::size_t>(s.w * s.h)) << label(spec);
    EXPECT_EQ(spec.node_count(), s.w * s.h) << label(spec);
    EXPECT_EQ(net.width(), s.w);
    EXPECT_EQ(net.height(), s.h);
    EXPECT_EQ(net.rest_positions().size(), net.node_count());
    EXPECT_EQ(net.masses().size(), net.node_count());
    EXPECT_EQ(net.pinned().size(), net.node_count());
    EXPECT_EQ(net.lod().leaf_count(), net.node_count()) << label(spec);
  }
}

TEST(Net, IndexIsRowMajorAlongX) {
  const Net net(net_spec(17, 9));
  EXPECT_EQ(net.index(0, 0), 0);
  EXPECT_EQ(net.index(1, 0), 1);
  EXPECT_EQ(net.index(0, 1), 17);
  EXPECT_EQ(net.index(16, 8), 17 * 9 - 1);
  EXPECT_EQ(net.index(5, 3), 3 * 17 + 5);
}

TEST(Net, LinkCountsMatchExpectedAndClosedFormulas) {
  for (const NetSize s : kNetSizes) {
    for (const bool shear : {false, true}) {
      for (const bool bend : {false, true}) {
        const NetSpec spec = net_spec(s.w, s.h, shear, bend);
        const Net net(spec);
        const std::size_t formula =
            structural_formula(s.w, s.h) + (shear ? shear_formula(s.w, s.h) : 0) + (bend ? bend_formula(s.w, s.h) : 0);
        EXPECT_EQ(net.links().size(), formula) << label(spec);
        EXPECT_EQ(expected_link_count(spec), formula) << label(spec);
        std::size_t by_kind[3] = {0, 0, 0};
        for (const NetLink& l : net.links()) ++by_kind[static_cast<int>(l.kind)];
        EXPECT_EQ(by_kind[static_cast<int>(LinkKind::kStructural)], structural_formula(s.w, s.h)) << label(spec);
        EXPECT_EQ(by_kind[static_cast<int>(LinkKind::kShear)], shear ? shear_formula(s.w, s.h) : 0) << label(spec);
        EXPECT_EQ(by_kind[static_cast<int>(LinkKind::kBend)], bend ? bend_formula(s.w, s.h) : 0) << label(spec);
      }
    }
  }
}

TEST(Net, KnownSmallLinkCounts) {
  // Hand-counted: 2x2 has 4 edges, 2 diagonals, no room for a bend; 3x7: 3*6 + 7*2 = 32 structural, 2*2*6 = 24
  // shear, 1*7 + 5*3 = 22 bend.
  EXPECT_EQ(Net(net_spec(2, 2)).links().size(), 4u);
  EXPECT_EQ(Net(net_spec(2, 2, true)).links().size(), 6u);
  EXPECT_EQ(Net(net_spec(2, 2, true, true)).links().size(), 6u);
  EXPECT_EQ(Net(net_spec(3, 7)).links().size(), 32u);
  EXPECT_EQ(Net(net_spec(3, 7, true)).links().size(), 56u);
  EXPECT_EQ(Net(net_spec(3, 7, false, true)).links().size(), 54u);
  EXPECT_EQ(Net(net_spec(3, 7, true, true)).links().size(), 78u);
  EXPECT_EQ(Net(net_spec(65, 65)).links().size(), 8320u);  // W(H-1) + H(W-1) structural links
}

TEST(Net, LinksJoinTheRightGridNeighboursOnceEach) {
  for (const NetSize s : kNetSizes) {
    const NetSpec spec = net_spec(s.w, s.h, true, true);
    const Net net(spec);
    std::set<std::pair<TreeId, TreeId>> seen;
    for (const NetLink& l : net.links()) {
      ASSERT_GE(l.a, 0);
      ASSERT_GE(l.b, 0);
      ASSERT_LT(static_cast<std::size_t>(l.a), net.node_count());
      ASSERT_LT(static_cast<std::size_t>(l.b), net.node_count());
      const int ax = l.a % s.w, ay = l.a / s.w, bx = l.b % s.w, by = l.b / s.w;
      const int dx = std::abs(bx - ax), dy = std::abs(by - ay);
      switch (l.kind) {
        case LinkKind::kStructural: EXPECT_EQ(dx + dy, 1) << label(spec); break;
        case LinkKind::kShear: EXPECT_TRUE(dx == 1 && dy == 1) << label(spec); break;
        case LinkKind::kBend: EXPECT_TRUE((dx == 2 && dy == 0) || (dx == 0 && dy == 2)) << label(spec); break;
      }
      EXPECT_TRUE(seen.insert(std::minmax(l.a, l.b)).second) << "duplicate link " << l.a << "-" << l.b;
    }
  }
}

TEST(Net, CanonicalOrderStartsWithPlusXThenPlusZ) {
  for (const NetSize s : kNetSizes) {
    const Net net(net_spec(s.w, s.h));
    ASSERT_GE(net.links().size(), 2u);
    EXPECT_EQ(net.links()[0].a, 0);
    EXPECT_EQ(net.links()[0].b, 1);
    EXPECT_EQ(net.links()[0].kind, LinkKind::kStructural);
    EXPECT_EQ(net.links()[1].a, 0);
    EXPECT_EQ(net.links()[1].b, s.w);
    EXPECT_EQ(net.links()[1].kind, LinkKind::kStructural);
  }
  // With shear and bend, node 0's links are +x, +z, the two diagonals of its cell, then the two bends.
  const int w = 17;
  const Net net(net_spec(w, 9, true, true));
  const std::vector<std::tuple<TreeId, TreeId, LinkKind>> first = {
      {0, 1, LinkKind::kStructural}, {0, w, LinkKind::kStructural}, {0, w + 1, LinkKind::kShear},
      {1, w, LinkKind::kShear},      {0, 2, LinkKind::kBend},       {0, 2 * w, LinkKind::kBend}};
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(net.links()[i].a, std::get<0>(first[i])) << "link " << i;
    EXPECT_EQ(net.links()[i].b, std::get<1>(first[i])) << "link " << i;
    EXPECT_EQ(net.links()[i].kind, std::get<2>(first[i])) << "link " << i;
  }
}

TEST(Net, StructuralOrderIsCreatePatchOrder) {
  // btSoftBodyHelpers::CreatePatch: for each node row-major, its +x link (if any) then its +z link (if any).
  for (const NetSize s : kNetSizes) {
    const Net net(net_spec(s.w, s.h));
    std::vector<std::pair<TreeId, TreeId>> patch;
    for (int y = 0; y < s.h; ++y)
      for (int x = 0; x < s.w; ++x) {
        const int i = y * s.w + x;
        if (x + 1 < s.w) patch.emplace_back(i, i + 1);
        if (y + 1 < s.h) patch.emplace_back(i, i + s.w);
      }
    ASSERT_EQ(net.links().size(), patch.size());
    for (std::size_t k = 0; k < patch.size(); ++k) {
      ASSERT_EQ(net.links()[k].a, patch[k].first) << s.w << "x" << s.h << " link " << k;
      ASSERT_EQ(net.links()[k].b, patch[k].second) << s.w << "x" << s.h << " link " << k;
    }
  }
}

TEST(Net, LinksOfEachNodeAreGroupedRowMajor) {
  // The first endpoint never decreases along the canonical order, shear diagonals of a cell included (their first
  // endpoint is the cell's min corner or its +x neighbour, listed with the min corner).
  const Net net(net_spec(9, 5, true, true));
  int cell_owner = -1;
  for (const NetLink& l : net.links()) {
    const int owner = l.kind == LinkKind::kShear && l.b == l.a + 9 - 1 ? l.a - 1 : l.a;
    EXPECT_GE(owner, cell_owner);
    cell_owner = owner;
  }
}

TEST(Net, RestPositionsSpanTheNetAtItsElevation) {
  for (const NetSize s : kNetSizes) {
    NetSpec spec = net_spec(s.w, s.h);
    spec.size_x = 6.0;
    spec.size_z = 2.5;
    spec.elevation = 3.25;
    const Net net(spec);
    double min_x = 1e9, max_x = -1e9, min_z = 1e9, max_z = -1e9;
    for (int y = 0; y < s.h; ++y) {
      for (int x = 0; x < s.w; ++x) {
        const Eigen::Vector3d& p = net.rest_positions()[static_cast<std::size_t>(net.index(x, y))];
        EXPECT_DOUBLE_EQ(p.y(), 3.25);
        EXPECT_NEAR(p.x(), -3.0 + 6.0 * x / (s.w - 1), 1e-12);
        EXPECT_NEAR(p.z(), -1.25 + 2.5 * y / (s.h - 1), 1e-12);
        min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
        min_z = std::min(min_z, p.z()), max_z = std::max(max_z, p.z());
      }
    }
    EXPECT_DOUBLE_EQ(min_x, -3.0) << label(spec);
    EXPECT_DOUBLE_EQ(max_x, 3.0) << label(spec);
    EXPECT_DOUBLE_EQ(min_z, -1.25) << label(spec);
    EXPECT_DOUBLE_EQ(max_z, 1.25) << label(spec);
    EXPECT_DOUBLE_EQ(net.extent(), 6.0);
  }
  NetSpec tall = net_spec(3, 7);
  tall.size_x = 1.0;
  tall.size_z = 4.0;
  EXPECT_DOUBLE_EQ(Net(tall).extent(), 4.0);
}

TEST(Net, TotalMassModeSpreadsTheMassEvenly) {
  for (const NetSize s : kNetSizes) {
    NetSpec spec = net_spec(s.w, s.h);
    spec.mass_mode = MassMode::kTotal;
    spec.mass = 2.5;
    const Net net(spec);
    for (double m : net.masses()) ASSERT_DOUBLE_EQ(m, 2.5 / (s.w * s.h)) << label(spec);
    EXPECT_NEAR(net.total_mass(), 2.5, 1e-12) << label(spec);
    EXPECT_DOUBLE_EQ(spec.node_mass(), 2.5 / (s.w * s.h));
  }
}

TEST(Net, PerNodeMassModeGivesEachNodeTheMass) {
  for (const NetSize s : kNetSizes) {
    NetSpec spec = net_spec(s.w, s.h);
    spec.mass_mode = MassMode::kPerNode;
    spec.mass = 0.125;
    const Net net(spec);
    for (double m : net.masses()) ASSERT_DOUBLE_EQ(m, 0.125) << label(spec);
    EXPECT_NEAR(net.total_mass(), 0.125 * s.w * s.h, 1e-9) << label(spec);
    EXPECT_DOUBLE_EQ(spec.node_mass(), 0.125);
  }
}

TEST(Net, PinnedCornersFollowTheBitFlags) {
  for (const NetSize s : kNetSizes) {
    for (unsigned mask = 0; mask <= kAllCorners; ++mask) {
      NetSpec spec = net_spec(s.w, s.h);
      spec.pinned_corners = mask;
      const Net net(spec);
      std::set<TreeId> expected;
      if (mask & kCornerMinMin) expected.insert(net.index(0, 0));
      if (mask & kCornerMaxMin) expected.insert(net.index(s.w - 1, 0));
      if (mask & kCornerMinMax) expected.insert(net.index(0, s.h - 1));
      if (mask & kCornerMaxMax) expected.insert(net.index(s.w - 1, s.h - 1));
      for (std::size_t i = 0; i < net.node_count(); ++i)
        ASSERT_EQ(net.pinned()[i] != 0, expected.count(static_cast<TreeId>(i)) == 1)
            << label(spec) << " mask " << mask << " node " << i;
    }
  }
  // The bit values are CreatePatch's `fixeds`.
  EXPECT_EQ(kCornerMinMin, 1u);
  EXPECT_EQ(kCornerMaxMin, 2u);
  EXPECT_EQ(kCornerMinMax, 4u);
  EXPECT_EQ(kCornerMaxMax, 8u);
  EXPECT_EQ(kAllCorners, 15u);
}

TEST(Net, PinnedCornerIsAtTheNamedPosition) {
  NetSpec spec = net_spec(5, 3);
  spec.pinned_corners = kCornerMaxMin;  // x max, z min
  const Net net(spec);
  for (std::size_t i = 0; i < net.node_count(); ++i) {
    if (!net.pinned()[i]) continue;
    EXPECT_DOUBLE_EQ(net.rest_positions()[i].x(), 0.5 * spec.size_x);
    EXPECT_DOUBLE_EQ(net.rest_positions()[i].z(), -0.5 * spec.size_z);
  }
}

TEST(Net, RejectsInvalidSpecs) {
  EXPECT_THROW(Net(net_spec(1, 5)), std::invalid_argument);
  EXPECT_THROW(Net(net_spec(5, 1)), std::invalid_argument);
  NetSpec no_mass = net_spec(3, 3);
  no_mass.mass = 0;
  EXPECT_THROW(Net{no_mass}, std::invalid_argument);
  NetSpec flat = net_spec(3, 3);
  flat.size_z = 0;
  EXPECT_THROW(Net{flat}, std::invalid_argument);
  EXPECT_NO_THROW(Net(net_spec(2, 2)));
  // Issue 60: values no cloth can have, named (a library user fills NetSpec in code; the suite parser bounds it).
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [field, edit] : std::vector<std::pair<std::string, std::function<void(NetSpec&)>>>{
           {"size_x", [&](NetSpec& n) { n.size_x = inf; }},
           {"size_z", [&](NetSpec& n) { n.size_z = inf; }},
           {"elevation", [&](NetSpec& n) { n.elevation = nan; }},
           {"elevation", [&](NetSpec& n) { n.elevation = -inf; }},
           {"mass", [&](NetSpec& n) { n.mass = inf; }}}) {
    NetSpec spec = net_spec(3, 3);
    edit(spec);
    try {
      Net net(spec);
      ADD_FAILURE() << field << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace tcsb
