// Net: one cloth net, shared and immutable once built — grid nodes, links and the LOD tree above them.
// Knows nothing of Bullet: the soft bodies map it onto Bullet's arrays.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "../net/lod_tree.h"
#include "../net/net_spec.h"

namespace tcsb {

/// What a link stands for in the mass-spring model.
enum class LinkKind : std::uint8_t { kStructural, kShear, kBend };

/// A link between two grid nodes (ids are leaf TreeIds, equal to row-major grid indices).
struct NetLink {
  TreeId a = 0, b = 0;
  LinkKind kind = LinkKind::kStructural;
};

/// The immutable net: rest positions, masses, pins, links in their canonical order, and the LOD tree.
class Net {
 public:
  /// Builds the net in O(N), its LOD tree's blocks resting as `rest` says (LodTree::rest()). Throws
  /// std::invalid_argument on a spec the suite parser should have rejected.
  Net(const NetSpec& spec, RestPlacement rest);
  /// ... resting as the spec says (NetSpec::lod_rest).
  explicit Net(const NetSpec& spec) : Net(spec, spec.lod_rest) {}

  const NetSpec& spec() const { return spec_; }
  int width() const { return spec_.width; }
  int height() const { return spec_.height; }
  std::size_t node_count() const { return rest_.size(); }
  /// Grid index of node (x, z): row-major along x, as btSoftBodyHelpers::CreatePatch numbers its nodes.
  TreeId index(int x, int y) const { return y * spec_.width + x; }

  std::span<const Eigen::Vector3d> rest_positions() const { return rest_; }
  std::span<const double> masses() const { return mass_; }
  std::span<const std::uint8_t> pinned() const { return pinned_; }
  /// Links in the canonical order: for each node row-major, the +x structural link, the +z structural link, then
  /// (if enabled) the two shear diagonals and the two bend links. For structural links alone this is exactly
  /// CreatePatch's order, so the plain baseline and stock Bullet solve their links in the same sequence.
  std::span<const NetLink> links() const { return links_; }
  const LodTree& lod() const { return *lod_; }
  double total_mass() const;
  /// The larger physical extent (x or z), the yardstick for drift and error percentages.
  double extent() const { return spec_.size_x > spec_.size_z ? spec_.size_x : spec_.size_z; }

 private:
  NetSpec spec_;
  std::vector<Eigen::Vector3d> rest_;
  std::vector<double> mass_;
  std::vector<std::uint8_t> pinned_;
  std::vector<NetLink> links_;
  std::unique_ptr<const LodTree> lod_;  // built after the leaves; Net is shared as shared_ptr<const Net>
};

/// Number of links a spec produces, without building it (for memory estimates and tests).
std::size_t expected_link_count(const NetSpec& spec);

}  // namespace tcsb
