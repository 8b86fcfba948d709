#include "feedback/surface_occlusion.h"

#include "feedback/saliency.h"
#include "softbody/tc_softbody_impl.h"

namespace tcsb {

void SurfaceOcclusion::capture(const TcSoftBody& body, CutSnapshot& snapshot) {
  // (a body with faces built them from the same triples at its last change: read, not derived again)
  const std::vector<std::array<TreeId, 3>>& faces = body.impl().current_cut_faces(tree_faces_, owner_);
  snapshot.faces.resize(faces.size());
  const auto index = [&](TreeId id) { return snapshot.cut.index[static_cast<std::size_t>(id)]; };
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::array<TreeId, 3>& t = faces[f];
    snapshot.faces[f] = {index(t[0]), index(t[1]), index(t[2])};
  }
}

std::span<const std::uint8_t> SurfaceOcclusion::seen(const CutSnapshot& snapshot, const ScreenProjection& view,
                                                     int cell_px) {
  const std::array<double, 3> key{static_cast<double>(cell_px), view.width_px(), view.height_px()};
  if (!buffer_ || key != buffer_key_) {
    buffer_.emplace(view, cell_px);
    buffer_key_ = key;
  }
  const std::size_t n = snapshot.size();
  image_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& x = snapshot.position[i];
    image_[i] = view.project(Eigen::Vector3d(x[0], x[1], x[2]));
  }
  buffer_->clear();
  for (const auto& f : snapshot.faces)
    buffer_->add_triangle(image_[static_cast<std::size_t>(f[0])], image_[static_cast<std::size_t>(f[1])],
                          image_[static_cast<std::size_t>(f[2])]);
  const LodTree& tree = *snapshot.cut.tree;
  const double spacing = grid_spacing(tree);
  seen_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    seen_[i] = buffer_->visible(image_[i], block_side(tree, snapshot.cut.tree_of[i], spacing)) ? 1 : 0;
  return seen_;
}

}  // namespace tcsb
