#include "net/lod_tree.h"

#include <stdexcept>

namespace tcsb {

LodTree::LodTree(int width, int height, std::span<const Eigen::Vector3d> leaf_rest, std::span<const double> leaf_mass,
                 std::span<const std::uint8_t> leaf_pinned, RestPlacement placement)
    : placement_(placement) {
  if (width < 1 || height < 1) throw std::invalid_argument("LodTree: grid must be at least 1x1");
  const std::size_t leaves = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (leaf_rest.size() != leaves || leaf_mass.size() != leaves || leaf_pinned.size() != leaves)
    throw std::invalid_argument("LodTree: per-leaf arrays must have width*height entries");

  // Level sizes first, so the node array is allocated once.
  std::size_t total = 0;
  for (int w = width, h = height;; w = (w + 1) / 2, h = (h + 1) / 2) {
    level_offset_.push_back(static_cast<TreeId>(total));
    level_width_.push_back(w);
    level_height_.push_back(h);
    total += static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    if (w == 1 && h == 1) break;
  }
  nodes_.resize(total);
  centroid_.resize(total);
  rest_.resize(total);

  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const TreeId id = at(0, x, y);
      LodNode& n = nodes_[static_cast<std::size_t>(id)];
      n.gx = x;
      n.gy = y;
      n.leaf_x0 = x, n.leaf_x1 = x + 1, n.leaf_y0 = y, n.leaf_y1 = y + 1;
      n.mass = leaf_mass[static_cast<std::size_t>(id)];
      const auto i = static_cast<std::size_t>(id);
      centroid_[i] = rest_[i] = leaf_rest[i];
      n.pinned_leaf_count = leaf_pinned[static_cast<std::size_t>(id)] ? 1 : 0;
      n.anchor_leaf = n.pinned_leaf_count ? id : kNoTreeNode;
    }
  }

  for (int level = 1; level < level_count(); ++level) {
    for (int gy = 0; gy < level_height(level); ++gy) {
      for (int gx = 0; gx < level_width(level); ++gx) {
        const TreeId id = at(level, gx, gy);
        LodNode& n = nodes_[static_cast<std::size_t>(id)];
        n.level = static_cast<std::int16_t>(level);
        n.gx = gx;
        n.gy = gy;
        Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
        int pinned = 0;
        bool first = true;
        for (int dy = 0; dy < 2; ++dy) {
          for (int dx = 0; dx < 2; ++dx) {
            const TreeId c = at(level - 1, 2 * gx + dx, 2 * gy + dy);
            if (c == kNoTreeNode) continue;
            LodNode& child = nodes_[static_cast<std::size_t>(c)];
            child.parent = id;
            n.children[static_cast<std::size_t>(n.child_count++)] = c;
            n.mass += child.mass;
            weighted += child.mass * centroid(c);
            pinned += child.pinned_leaf_count;
            if (child.anchor_leaf != kNoTreeNode) n.anchor_leaf = child.anchor_leaf;
            if (first) {
              n.leaf_x0 = child.leaf_x0, n.leaf_y0 = child.leaf_y0;
              first = false;
            }
            n.leaf_x1 = child.leaf_x1, n.leaf_y1 = child.leaf_y1;
          }
        }
        n.pinned_leaf_count = static_cast<std::int8_t>(pinned > 100 ? 100 : pinned);
        const auto i = static_cast<std::size_t>(id);
        centroid_[i] = n.mass > 0 ? Eigen::Vector3d(weighted / n.mass) : Eigen::Vector3d::Zero();
        if (n.pinned_leaf_count != 1) n.anchor_leaf = kNoTreeNode;
        rest_[i] = n.anchor_leaf != kNoTreeNode ? rest(n.anchor_leaf) : centroid_[i];
        if (n.anchor_leaf == kNoTreeNode && placement == RestPlacement::kVertex) {
          // On the first leaf, or on the last border along an axis the block touches only there: leaf columns and
          // rows 0, 2^k, 2 * 2^k, ... (docs/investigations/lod-rest-placement.md). Along an axis the block spans
          // whole, its centroid.
          const bool span_x = n.leaf_x0 == 0 && n.leaf_x1 == width, span_y = n.leaf_y0 == 0 && n.leaf_y1 == height;
          const Eigen::Vector3d& vertex = leaf_rest[static_cast<std::size_t>(rest_leaf(id))];
          if (!span_x && !span_y) {
            rest_[i] = vertex;
          } else {
            if (!span_x) rest_[i].x() = vertex.x();
            if (!span_y) rest_[i].z() = vertex.z();
          }
        } else if (n.anchor_leaf == kNoTreeNode) {
          // A block touching one border along an axis rests on that border, as a uniform grid's edge node does
          // (docs/methodology.md, "Why calibrated TC-SB errs more than the calibrated grid").
          if ((n.leaf_x0 == 0) != (n.leaf_x1 == width))
            rest_[i].x() = leaf_rest[static_cast<std::size_t>(at(0, n.leaf_x0 == 0 ? 0 : width - 1, n.leaf_y0))].x();
          if ((n.leaf_y0 == 0) != (n.leaf_y1 == height))
            rest_[i].z() = leaf_rest[static_cast<std::size_t>(at(0, n.leaf_x0, n.leaf_y0 == 0 ? 0 : height - 1))].z();
        }
      }
    }
  }
  rank_block_centres();
}

void LodTree::rank_block_centres() {
  // Twice a block's centre in leaf units, so that every centre is an integer: leaf (x, y) is at (2x, 2y). Two
  // stable counting sorts, column first, then row: O(size + width + height).
  const auto size = nodes_.size();
  const auto column = [&](std::size_t i) {
    return static_cast<std::size_t>(nodes_[i].leaf_x0 + nodes_[i].leaf_x1 - 1);
  };
  const auto row = [&](std::size_t i) { return static_cast<std::size_t>(nodes_[i].leaf_y0 + nodes_[i].leaf_y1 - 1); };
  std::vector<std::int32_t> by_column(size), by_row(size);
  const auto counting_sort = [&](const auto& key, std::size_t keys, const auto& in, std::vector<std::int32_t>& out) {
    std::vector<std::size_t> start(keys + 1, 0);
    for (std::size_t k = 0; k < size; ++k) ++start[key(in(k)) + 1];
    for (std::size_t k = 0; k < keys; ++k) start[k + 1] += start[k];
    for (std::size_t k = 0; k < size; ++k) out[start[key(in(k))]++] = static_cast<std::int32_t>(in(k));
  };
  counting_sort(
      column, 2 * static_cast<std::size_t>(level_width(0)), [](std::size_t k) { return k; }, by_column);
  counting_sort(
      row, 2 * static_cast<std::size_t>(level_height(0)),
      [&](std::size_t k) { return static_cast<std::size_t>(by_column[k]); }, by_row);
  spatial_rank_.resize(size);
  for (std::size_t r = 0; r < size; ++r)
    spatial_rank_[static_cast<std::size_t>(by_row[r])] = static_cast<std::int32_t>(r);
}

}  // namespace tcsb
