#include "feedback/unseen_body.h"

#include <algorithm>
#include <limits>

#include "feedback/saliency.h"

namespace tcsb {

bool unseen_in(const CutSnapshot& snapshot, std::span<const ScreenProjection> views) {
  if (snapshot.size() == 0) return false;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  const LodTree& tree = *snapshot.cut.tree;
  const double spacing = grid_spacing(tree);
  double largest_side = 0;
  for (std::size_t i = 0; i < snapshot.size(); ++i) {
    const std::array<float, 3>& p = snapshot.position[i];
    const Eigen::Vector3d x(p[0], p[1], p[2]);
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
    largest_side = std::max(largest_side, block_side(tree, snapshot.cut.tree_of[i], spacing));
  }
  lo.array() -= largest_side;
  hi.array() += largest_side;
  return std::none_of(views.begin(), views.end(),
                      [&](const ScreenProjection& view) { return view.may_see_box(lo, hi); });
}

}  // namespace tcsb
