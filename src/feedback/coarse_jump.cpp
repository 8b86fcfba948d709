#include "feedback/coarse_jump.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <optional>

#include "softbody/affine_fit.h"

namespace tcsb {

namespace {

using Fit = Eigen::Matrix<double, 3, 2>;

Eigen::Vector3d position(const CutSnapshot& snapshot, std::int32_t index) {
  const std::array<float, 3>& p = snapshot.position[static_cast<std::size_t>(index)];
  return {p[0], p[1], p[2]};
}

Eigen::Vector2d plane(const Eigen::Vector3d& rest_offset) { return {rest_offset.x(), rest_offset.z()}; }

/// Accumulates one point (offset from the fit's origin) into the fit's sums.
void add_point(const Eigen::Vector3d& dx, const Eigen::Vector2d& dr, Eigen::Matrix2d& rr, Fit& xr) {
  rr += dr * dr.transpose();
  xr += dx * dr.transpose();
}

}  // namespace

void cut_neighbours(const CutView& cut, CutNeighbours& out) {
  const std::size_t n = cut.size();
  out.start.assign(n + 1, 0);
  const auto committed_link = [&](const CutLink& l) {
    return l.joins_committed() && cut.committed(l.a) && cut.committed(l.b);
  };
  for (const CutLink& l : cut.links) {
    if (!committed_link(l)) continue;
    ++out.start[static_cast<std::size_t>(cut.index[static_cast<std::size_t>(l.a)]) + 1];
    ++out.start[static_cast<std::size_t>(cut.index[static_cast<std::size_t>(l.b)]) + 1];
  }
  for (std::size_t i = 0; i < n; ++i) out.start[i + 1] += out.start[i];
  out.other.resize(static_cast<std::size_t>(out.start[n]));
  std::vector<std::int32_t> fill(out.start.begin(), out.start.end() - 1);
  for (const CutLink& l : cut.links) {
    if (!committed_link(l)) continue;
    const std::int32_t a = cut.index[static_cast<std::size_t>(l.a)], b = cut.index[static_cast<std::size_t>(l.b)];
    out.other[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
    out.other[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
  }
}

namespace {

/// The largest `distance(before, after)` over the corners of every child's block of `parent` (coarse_jump.h).
template <class Distance>
double largest_corner_jump(const CutSnapshot& snapshot, const CutNeighbours& neighbours, TreeId parent,
                           Distance distance) {
  const LodTree& tree = *snapshot.cut.tree;
  const LodNode& p = tree.node(parent);
  const auto index_of = [&](TreeId id) { return snapshot.cut.index[static_cast<std::size_t>(id)]; };
  const auto rest_of_index = [&](std::int32_t i) {
    return tree.rest(snapshot.cut.tree_of[static_cast<std::size_t>(i)]);
  };

  // Where begin_coarse puts the parent: its children's centre of mass (where the pins are now if it holds one: its
  // rest position moved by the pin path; where their fit puts its rest position if it rests on the net's border).
  std::array<Eigen::Vector3d, 4> child_x;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  double mass = 0;
  for (int k = 0; k < p.child_count; ++k) {
    const TreeId c = p.children[static_cast<std::size_t>(k)];
    child_x[static_cast<std::size_t>(k)] = position(snapshot, index_of(c));
    weighted += tree.node(c).mass * child_x[static_cast<std::size_t>(k)];
    mass += tree.node(c).mass;
  }
  const Eigen::Vector3d rp = tree.rest(parent);
  const std::array<float, 3>& pins = snapshot.cut.pin_offset;
  const Eigen::Vector3d pinned_at = rp + Eigen::Vector3d(pins[0], pins[1], pins[2]);
  Eigen::Vector3d xp = p.pinned() ? pinned_at : mass <= 0 ? rp : Eigen::Vector3d(weighted / mass);
  if (const std::optional<Eigen::Vector3d> border = border_arrival(tree, parent, child_x)) xp = *border;

  // The parent's fit while it arrives: its tethers to the children and its links to their outside neighbours.
  Eigen::Matrix2d rr = Eigen::Matrix2d::Zero();
  Fit xr = Fit::Zero();
  std::array<std::int32_t, 4> child_index{-1, -1, -1, -1};
  for (int k = 0; k < p.child_count; ++k)
    child_index[static_cast<std::size_t>(k)] = index_of(p.children[static_cast<std::size_t>(k)]);
  const auto is_child = [&](std::int32_t i) {
    return std::find(child_index.begin(), child_index.begin() + p.child_count, i) !=
           child_index.begin() + p.child_count;
  };
  std::array<std::int32_t, 32> outside{};
  int outside_count = 0;
  for (int k = 0; k < p.child_count; ++k) {
    const std::int32_t c = child_index[static_cast<std::size_t>(k)];
    add_point(child_x[static_cast<std::size_t>(k)] - xp, plane(rest_of_index(c) - rp), rr, xr);
    for (std::int32_t e = neighbours.start[static_cast<std::size_t>(c)];
         e < neighbours.start[static_cast<std::size_t>(c) + 1]; ++e) {
      const std::int32_t n = neighbours.other[static_cast<std::size_t>(e)];
      if (is_child(n)) continue;
      const auto end = outside.begin() + outside_count;
      if (std::find(outside.begin(), end, n) != end) continue;  // a neighbour of two children: one link to P
      if (outside_count < static_cast<int>(outside.size())) outside[static_cast<std::size_t>(outside_count++)] = n;
      add_point(position(snapshot, n) - xp, plane(rest_of_index(n) - rp), rr, xr);
    }
  }
  const Fit fp = solve_affine_fit(rr, xr);

  // Before against after at the corners of every child's block.
  const int width = tree.level_width(0);
  double jump = 0;
  for (int k = 0; k < p.child_count; ++k) {
    const TreeId c = p.children[static_cast<std::size_t>(k)];
    const LodNode& cn = tree.node(c);
    const Eigen::Vector3d& xc = child_x[static_cast<std::size_t>(k)];
    const Eigen::Vector3d rc = tree.rest(c);
    if (cn.is_leaf()) {
      jump = std::max(jump, distance(xc, Eigen::Vector3d(xp + fp * plane(rc - rp))));
      continue;
    }
    Eigen::Matrix2d crr = Eigen::Matrix2d::Zero();
    Fit cxr = Fit::Zero();
    const std::int32_t ci = child_index[static_cast<std::size_t>(k)];
    for (std::int32_t e = neighbours.start[static_cast<std::size_t>(ci)];
         e < neighbours.start[static_cast<std::size_t>(ci) + 1]; ++e) {
      const std::int32_t n = neighbours.other[static_cast<std::size_t>(e)];
      add_point(position(snapshot, n) - xc, plane(rest_of_index(n) - rc), crr, cxr);
    }
    const Fit fc = solve_affine_fit(crr, cxr);
    for (const int gy : {cn.leaf_y0, cn.leaf_y1 - 1})
      for (const int gx : {cn.leaf_x0, cn.leaf_x1 - 1}) {
        const Eigen::Vector3d rl = tree.rest(static_cast<TreeId>(gy * width + gx));
        const Eigen::Vector3d before = xc + fc * plane(rl - rc);
        const Eigen::Vector3d after = xp + fp * plane(rl - rp);
        jump = std::max(jump, distance(before, after));
      }
  }
  return jump;
}

}  // namespace

double coarse_jump(const CutSnapshot& snapshot, const CutNeighbours& neighbours, TreeId parent) {
  return largest_corner_jump(snapshot, neighbours, parent,
                             [](const Eigen::Vector3d& before, const Eigen::Vector3d& after) {
                               return (before - after).norm();
                             });
}

double coarse_jump_px(const CutSnapshot& snapshot, const CutNeighbours& neighbours, TreeId parent,
                      const ScreenProjection& view) {
  return largest_corner_jump(snapshot, neighbours, parent,
                             [&view](const Eigen::Vector3d& before, const Eigen::Vector3d& after) {
                               const ScreenPoint seen = view.project(before);
                               return seen.in_view ? view.displacement_px(after, seen) : 0.0;
                             });
}

}  // namespace tcsb
