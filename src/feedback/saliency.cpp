#include "feedback/saliency.h"

#include <algorithm>
#include <cmath>

#include "net/cut_adjacency.h"

namespace tcsb {

void neighbour_sums(const CutSnapshot& snapshot, NeighbourSums& out) {
  const CutView& cut = snapshot.cut;
  out.sum.assign(snapshot.size(), {0.0f, 0.0f, 0.0f});
  out.count.assign(snapshot.size(), 0);
  for (const CutLink& link : cut.links) {
    if (!link.joins_committed()) continue;
    const auto a = static_cast<std::size_t>(cut.index[static_cast<std::size_t>(link.a)]);
    const auto b = static_cast<std::size_t>(cut.index[static_cast<std::size_t>(link.b)]);
    const auto& va = snapshot.velocity[a];
    const auto& vb = snapshot.velocity[b];
    for (std::size_t k = 0; k < 3; ++k) {
      out.sum[a][k] += vb[k];
      out.sum[b][k] += va[k];
    }
    ++out.count[a];
    ++out.count[b];
  }
}

namespace {
Eigen::Vector3d vec(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }

/// How much of a detail the spectator sees in simulated node i: its block's side on the image, over detail_px,
/// capped at 1. `facing`: as it would look were the camera turned to it (a node the spectator does not see now).
double apparent_detail(const CutSnapshot& snapshot, std::size_t i, const ScreenProjection& view, double leaf_spacing,
                       double detail_px, bool facing = false) {
  const double side = block_side(*snapshot.cut.tree, snapshot.cut.tree_of[i], leaf_spacing);
  const Eigen::Vector3d x = vec(snapshot.position[i]);
  return std::min(1.0, (facing ? view.facing_size_px(x, side) : view.apparent_size_px(x, side)) / detail_px);
}
}  // namespace

double grid_spacing(const LodTree& tree) { return tree.leaf_count() > 1 ? (tree.rest(1) - tree.rest(0)).norm() : 0.0; }

double block_side(const LodTree& tree, TreeId id, double spacing) {
  const LodNode& node = tree.node(id);
  return spacing * std::max(node.leaf_x1 - node.leaf_x0, node.leaf_y1 - node.leaf_y0);
}

void local_motion(const CutSnapshot& snapshot, const NeighbourSums& sums, std::size_t begin, std::size_t end,
                  std::span<float> out, const ScreenProjection* view) {
  for (std::size_t i = begin; i < end; ++i) {
    const int count = sums.count[i];
    if (count == 0 || !snapshot.cut.committed(snapshot.cut.tree_of[i])) {
      out[i] = 0;
      continue;
    }
    const auto& v = snapshot.velocity[i];
    const auto& s = sums.sum[i];
    const float dx = v[0] - s[0] / count, dy = v[1] - s[1] / count, dz = v[2] - s[2] / count;
    if (view) {
      const Eigen::Vector3d x = vec(snapshot.position[i]);
      out[i] = view->project(x).in_view
                   ? static_cast<float>(view->pixel_speed(x, {dx, dy, dz}) * view->degrees_per_pixel())
                   : 0.0f;
      continue;
    }
    out[i] = std::sqrt(dx * dx + dy * dy + dz * dz);
  }
}

double global_motion(const CutSnapshot& snapshot) {
  const LodTree& tree = *snapshot.cut.tree;
  double p[3] = {0, 0, 0}, mass = 0;
  for (std::size_t i = 0; i < snapshot.size(); ++i) {
    const TreeId id = snapshot.cut.tree_of[i];
    if (!snapshot.cut.committed(id)) continue;
    const double m = tree.node(id).mass;
    for (int k = 0; k < 3; ++k) p[k] += m * snapshot.velocity[i][static_cast<std::size_t>(k)];
    mass += m;
  }
  if (mass <= 0) return 0;
  return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / mass;
}

double projected_global_motion(const CutSnapshot& snapshot, const ScreenProjection& view) {
  const LodTree& tree = *snapshot.cut.tree;
  Eigen::Vector3d x = Eigen::Vector3d::Zero(), p = Eigen::Vector3d::Zero();
  double mass = 0;
  for (std::size_t i = 0; i < snapshot.size(); ++i) {
    const TreeId id = snapshot.cut.tree_of[i];
    if (!snapshot.cut.committed(id)) continue;
    const double m = tree.node(id).mass;
    x += m * vec(snapshot.position[i]);
    p += m * vec(snapshot.velocity[i]);
    mass += m;
  }
  if (mass <= 0) return 0;
  return view.pixel_speed(x / mass, p / mass) * view.degrees_per_pixel();
}

double global_motion_cap(double speed, double scale) { return 1.0 / (1.0 + speed / scale); }

double lambert_factor(const CutSnapshot& snapshot, std::size_t i, const std::array<double, 3>& light) {
  // Tangents along the net's x and z from the neighbours on either side (rest offsets tell the side), n = tz x tx:
  // for the flat net at rest that is +y.
  const LodTree& tree = *snapshot.cut.tree;
  const TreeId id = snapshot.cut.tree_of[i];
  const auto& xi = snapshot.position[i];
  const Eigen::Vector3d ri = tree.rest(id);
  double tx[3] = {0, 0, 0}, tz[3] = {0, 0, 0};
  for_each_cut_neighbour(
      tree, id, [&](TreeId n) { return snapshot.cut.committed(n); },
      [&](TreeId n) {
        const auto& xn = snapshot.position[static_cast<std::size_t>(snapshot.cut.index[static_cast<std::size_t>(n)])];
        const Eigen::Vector3d dr = tree.rest(n) - ri;
        const bool along_x = std::abs(dr.x()) >= std::abs(dr.z());
        const double sign = along_x ? (dr.x() > 0 ? 1 : -1) : (dr.z() > 0 ? 1 : -1);
        double* t = along_x ? tx : tz;
        for (int k = 0; k < 3; ++k) t[k] += sign * (xn[static_cast<std::size_t>(k)] - xi[static_cast<std::size_t>(k)]);
      });
  const double n[3] = {tz[1] * tx[2] - tz[2] * tx[1], tz[2] * tx[0] - tz[0] * tx[2], tz[0] * tx[1] - tz[1] * tx[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double llen = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
  if (len <= 0 || llen <= 0) return 1.0;
  return std::max(0.0, (n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / (len * llen));
}

void finish_saliency(const CutSnapshot& snapshot, const FeedbackSettings& settings, std::span<float> motion,
                     const ScreenProjection* view, std::span<const std::uint8_t> seen) {
  // A hidden node's motion, as one out of view, is nothing the spectator sees: it must not scale the others'.
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (!seen[i]) motion[i] = 0;
  float largest = 0;
  for (float m : motion) largest = std::max(largest, m);
  const double cap = view ? global_motion_cap(projected_global_motion(snapshot, *view), settings.view_motion_scale)
                          : global_motion_cap(global_motion(snapshot), settings.global_motion_scale);
  const double leaf_spacing = view ? grid_spacing(*snapshot.cut.tree) : 0.0;
  for (std::size_t i = 0; i < motion.size(); ++i) {
    double s = largest > 0 ? motion[i] / largest : 0.0;
    s = std::min(s, cap);
    // Seen, a block is worth its apparent size times a mix of a static share and its motion, so with a static share
    // above 0 a quiet block in view still outranks every block out of view, at rest too. A node leaving the cut is
    // worth nothing, as without the view terms.
    if (view)
      s = snapshot.cut.committed(snapshot.cut.tree_of[i])
              ? apparent_detail(snapshot, i, *view, leaf_spacing, settings.view_detail_px) *
                    (settings.view_static_share + (1.0 - settings.view_static_share) * s)
              : 0.0;
    if (settings.illumination && s > 0) s *= lambert_factor(snapshot, i, settings.light_direction);
    if (!snapshot.contact.empty() && snapshot.contact[i]) s = std::max(s, settings.contact_saliency);
    // What the spectator cannot see, out of view or hidden by the body's surface, gets the lowest saliency, contact
    // included: nothing, or with view_offscreen_share its share of what its size would be worth in view.
    if (view && (!view->project(vec(snapshot.position[i])).in_view || (!seen.empty() && !seen[i])))
      s = settings.view_offscreen_share > 0 && snapshot.cut.committed(snapshot.cut.tree_of[i])
              ? settings.view_offscreen_share *
                    apparent_detail(snapshot, i, *view, leaf_spacing, settings.view_detail_px, /*facing=*/true)
              : 0.0;
    motion[i] = static_cast<float>(s);
  }
}

std::vector<float> compute_saliency(const CutSnapshot& snapshot, const FeedbackSettings& settings,
                                    const ScreenProjection* view, std::span<const std::uint8_t> seen) {
  std::vector<float> s(snapshot.size());
  NeighbourSums sums;
  neighbour_sums(snapshot, sums);
  local_motion(snapshot, sums, 0, snapshot.size(), s, view);
  finish_saliency(snapshot, settings, s, view, seen);
  return s;
}

}  // namespace tcsb
