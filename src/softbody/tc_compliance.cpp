// TcSoftBody under the compliant material (material.h; docs/design.md, "The material"): each link's stiffness from
// the membrane rule with the cells of the cut on either side of it, so a link inside any whole level carries the same
// stiffness Y, a link on the net's border Y/2, and a link where levels meet what the cells actually beside it give.
//
// The cells are those of a tree whose blocks rest on their first leaf (masses that follow the cut need one, and the
// compliant material needs those masses): a block's cell runs from its node to the nodes at its far corners
// (CornerShares), so the cells of a cut tile the net between its nodes.
#include <algorithm>
#include <limits>

#include "softbody/compliant_solver.h"
#include "softbody/tc_softbody_impl.h"

namespace tcsb {

double TcSoftBody::Impl::segment_stiffness(int xa, int za, int xb, int zb, bool committed) const {
  const int width = tree().level_width(0), height = tree().level_height(0);
  const bool along_x = za == zb;
  // In the segment's own frame: `u` along it, `v` across it.
  int u0 = along_x ? xa : za, u1 = along_x ? xb : zb;
  if (u0 > u1) std::swap(u0, u1);
  const int v = along_x ? za : xa, v_last = along_x ? height - 1 : width - 1;
  const int u_last = along_x ? width - 1 : height - 1;
  double area = 0;  // in leaf cells
  // One side: the cells holding the row of leaves at `row` across, each adding its overlap with the segment times
  // its extent on this side of the segment.
  const auto side = [&](int row, bool beyond) {
    for (int u = u0; u < u1;) {
      const TreeId c = along_x ? holding(u, row, committed) : holding(row, u, committed);
      const CornerShares& cell = corner_shares_[static_cast<std::size_t>(c)];
      const int next_u = along_x ? cell.next_x : cell.next_z;
      const int cv = along_x ? cell.z : cell.x, next_v = along_x ? cell.next_z : cell.next_x;
      const int end = std::min(next_u >= 0 ? next_u : u_last, u1);
      if (end <= u) break;  // (a cell of no extent: the net's last row or column)
      const int far = next_v >= 0 ? next_v : v_last;
      area += static_cast<double>(end - u) * static_cast<double>(beyond ? far - v : v - cv);
      u = end;
    }
  };
  if (v < v_last) side(v, true);
  if (v > 0) side(v - 1, false);
  const NetSpec& spec = net_->spec();
  const double hx = spec.size_x / (width - 1), hz = spec.size_z / (height - 1);
  return along_x ? grid_link_stiffness(solver_, area, u1 - u0, hx, hz)
                 : grid_link_stiffness(solver_, area, u1 - u0, hz, hx);
}

double TcSoftBody::Impl::link_stiffness(int link) const {
  const CutLink& meta = link_meta_[static_cast<std::size_t>(link)];
  const CornerShares& a = corner_shares_[static_cast<std::size_t>(meta.a)];
  const CornerShares& b = corner_shares_[static_cast<std::size_t>(meta.b)];
  if (meta.role == LinkRole::kTether || (a.x != b.x && a.z != b.z) || (a.x == b.x && a.z == b.z))
    return solver_.compliant.stretch_stiffness;  // an operation's tether (or a slanted handle): a grid link's
  return segment_stiffness(a.x, a.z, b.x, b.z, meta.joins_committed());
}

double TcSoftBody::Impl::interface_link_stiffness(const InterfaceConstraint& c, TreeId corner) const {
  // The far kind holds a fine node that lies on the coarse cell's edge at the edge's midpoint: an interpolated point
  // of the coarse cloth, not cloth of its own (x_h = (x_a + x_b) / 2), so it is held without compliance.
  if (c.kind == InterfaceKind::kVertexFar) return std::numeric_limits<double>::infinity();
  if (c.kind == InterfaceKind::kVertexNear && corner != kNoTreeNode) {
    // The fine node's link to the point of the coarse side between the coarse node and the corner's node.
    const CornerShares& hanging = corner_shares_[static_cast<std::size_t>(c.fine[c.kept == 0 ? 1 : 0])];
    const CornerShares& from = corner_shares_[static_cast<std::size_t>(c.coarse)];
    const CornerShares& to = corner_shares_[static_cast<std::size_t>(corner)];
    const int px = (from.x + to.x) / 2, pz = (from.z + to.z) / 2;
    if ((px == hanging.x) != (pz == hanging.z)) return segment_stiffness(hanging.x, hanging.z, px, pz, true);
  }
  return solver_.compliant.stretch_stiffness;  // (a midpoint constraint, or one that falls back to a plain link)
}

btScalar TcSoftBody::Impl::compliant_constant(btScalar w, double k, double alpha) const {
  double c0 = compliant_link_constant(w, k, solver_.substep_dt());
  if (alpha != 1.0) c0 /= alpha;
  return static_cast<btScalar>(c0);
}

}  // namespace tcsb
