// TcSoftBody's faces: the committed cut triangulated for Bullet's aerodynamic model (tc_softbody.h, enable_faces).
//
// A cut is a partition of the grid's leaves into blocks, and each simulated node stands at its block's rest point.
// The faces are the cut's dual: at every interior corner of the leaf cells, the (up to four) blocks around it form a
// quad when all four differ, a triangle when three do (a T-junction between levels), nothing when two or one do (the
// corner lies on one block's side or inside it). On the finest cut every corner is a grid cell, split as a plain
// body's cell is; on a balanced cut the faces tile the net at rest, which validate() checks by their total area.
#include <algorithm>
#include <cmath>
#include <string>

#include "softbody/bullet_setup.h"
#include "softbody/tc_softbody_impl.h"

namespace tcsb {

namespace {

/// Whether the block holding cell k of the four around a leaf corner (in ring order) has that corner as a corner of
/// its own: a block is a rectangle, so it does exactly when it holds neither neighbouring cell of the ring. Read from
/// the owners alone, without the block's record.
bool corner_of_own(const std::array<TreeId, 4>& around, std::size_t k) {
  return around[(k + 3) % 4] != around[k] && around[(k + 1) % 4] != around[k];
}

/// Twice the signed area of triangle (a, b, c) at rest, seen in the net's plane: the y component of
/// (b - a) x (c - a). A cell split as a plain body splits it gives a negative value.
btScalar rest_turn(const btVector3& a, const btVector3& b, const btVector3& c) { return btCross(b - a, c - a).y(); }

}  // namespace

void TcSoftBody::Impl::cut_faces(std::vector<std::array<TreeId, 3>>& out, std::vector<TreeId>& owner) const {
  out.clear();
  const LodTree& lod = tree();
  const int width = lod.level_width(0), height = lod.level_height(0);
  // Which committed block holds each leaf: every block writes its own rectangle, one write per leaf in all. Walking
  // up the levels from each corner's cells instead reads only the cut's corners, but cost 3.3 times the instructions
  // (callgrind, 40 steps of suites/flag.json's 65^2 net at 30 %: 18.0 M against 5.5 M).
  owner.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), kNoTreeNode);
  for (const TreeId id : tree_of_) {
    if (!committed(id)) continue;
    const LodNode& node = lod.node(id);
    for (int y = node.leaf_y0; y < node.leaf_y1; ++y) {
      const auto row = owner.begin() + static_cast<std::ptrdiff_t>(y) * width;
      std::fill(row + node.leaf_x0, row + node.leaf_x1, id);
    }
  }
  const auto owner_of = [&](int x, int y) { return owner[static_cast<std::size_t>(y) * width + x]; };
  // In Bullet's node order, each committed node emits the corners it is the first block around (in the ring order
  // below) to have as a corner of its own: every corner once, and on the finest cut each node the cell up and right
  // of it, in row-major order, as a plain body's faces go.
  for (const TreeId id : tree_of_) {
    if (!committed(id)) continue;
    const LodNode& node = lod.node(id);
    for (const int cy : {node.leaf_y0, node.leaf_y1}) {
      for (const int cx : {node.leaf_x0, node.leaf_x1}) {
        if (cx <= 0 || cy <= 0 || cx >= width || cy >= height) continue;  // the net's border: no cell beyond
        // Counter-clockwise around the corner in grid order: (-x,-y), (+x,-y), (+x,+y), (-x,+y).
        const std::array<TreeId, 4> around{owner_of(cx - 1, cy - 1), owner_of(cx, cy - 1), owner_of(cx, cy),
                                           owner_of(cx - 1, cy)};
        if (std::find(around.begin(), around.end(), kNoTreeNode) != around.end()) continue;
        std::size_t first = 0;
        while (!corner_of_own(around, first)) ++first;  // (id's own cell is among them: the search ends)
        if (around[first] != id) continue;
        std::array<TreeId, 4> ring{};
        int size = 0;
        for (const TreeId t : around)
          if (size == 0 || ring[static_cast<std::size_t>(size - 1)] != t) ring[static_cast<std::size_t>(size++)] = t;
        if (size > 1 && ring[static_cast<std::size_t>(size - 1)] == ring[0]) --size;
        if (size == 3) out.push_back({ring[0], ring[1], ring[2]});
        if (size != 4) continue;
        // Split along ring[0]-ring[2] as a plain cell is, unless a block of another level makes that quad concave
        // there: then along ring[1]-ring[3], so no triangle folds over.
        const auto at = [&](int k) { return record(ring[static_cast<std::size_t>(k)]).rest_position(); };
        if (rest_turn(at(0), at(1), at(2)) < 0 && rest_turn(at(0), at(2), at(3)) < 0) {
          out.push_back({ring[0], ring[1], ring[2]});
          out.push_back({ring[0], ring[2], ring[3]});
        } else {
          out.push_back({ring[0], ring[1], ring[3]});
          out.push_back({ring[1], ring[2], ring[3]});
        }
      }
    }
  }
}

const std::vector<std::array<TreeId, 3>>& TcSoftBody::Impl::current_cut_faces(std::vector<std::array<TreeId, 3>>& out,
                                                                              std::vector<TreeId>& owner) const {
  if (faces_enabled_ && !faces_stale_) return face_scratch_;
  cut_faces(out, owner);
  return out;
}

void TcSoftBody::Impl::enable_faces() {
  if (faces_enabled_) return;
  faces_enabled_ = true;
  // The most a cut can have: the finest one's two per cell.
  const LodTree& lod = tree();
  body_.m_faces.reserve(2 * (lod.level_width(0) - 1) * (lod.level_height(0) - 1));
  faces_stale_ = true;
  refresh_faces();
}

void TcSoftBody::Impl::refresh_faces() {
  if (!faces_enabled_ || !faces_stale_) return;
  faces_stale_ = false;
  ++face_rebuilds_;
  cut_faces(face_scratch_, owner_scratch_);
  body_.m_faces.resize(0);
  Node* const base = &body_.m_nodes[0];
  for (const auto& f : face_scratch_) append_face(body_, bullet_index(f[0]), bullet_index(f[1]), bullet_index(f[2]));
  // Areas at rest, as a plain body's are (Bullet computes them once, at rest, and never again): each face's the
  // doubled area Bullet's AreaOf gives, each node's the mean of its faces' (btSoftBody::updateArea), from the rest
  // points of the blocks, so a refine or coarse does not take the stretched shape of the moment for the cloth's.
  const int n = body_.m_nodes.size();
  area_scratch_.assign(2 * static_cast<std::size_t>(n), 0);
  for (int i = 0; i < body_.m_faces.size(); ++i) {
    Face& face = body_.m_faces[i];
    const auto& ids = face_scratch_[static_cast<std::size_t>(i)];
    face.m_ra = btCross(record(ids[1]).rest_position() - record(ids[0]).rest_position(),
                        record(ids[2]).rest_position() - record(ids[0]).rest_position())
                    .length();
    for (Node* corner : face.m_n) {
      const auto k = static_cast<std::size_t>(corner - base);
      area_scratch_[k] += btFabs(face.m_ra);
      area_scratch_[static_cast<std::size_t>(n) + k] += 1;
    }
  }
  for (int i = 0; i < n; ++i) {
    const btScalar count = area_scratch_[static_cast<std::size_t>(n + i)];
    body_.m_nodes[i].m_area = count > 0 ? area_scratch_[static_cast<std::size_t>(i)] / count : btScalar(0);
  }
  body_
      .updateNormals();  // what the step's aerodynamics reads; Bullet's integrateMotion would do it only after the step
}

void TcSoftBody::Impl::validate_faces(const ProblemSink& fail) const {
  if (!faces_enabled_) {
    if (body_.m_faces.size() != 0) fail("faces present without enable_faces()");
    return;
  }
  if (faces_stale_) return;  // rebuilt before the next step: checked then
  std::vector<std::array<TreeId, 3>> expected;
  std::vector<TreeId> owner;
  cut_faces(expected, owner);
  if (static_cast<std::size_t>(body_.m_faces.size()) != expected.size()) {
    fail(std::to_string(body_.m_faces.size()) + " faces where the committed cut has " +
         std::to_string(expected.size()));
    return;
  }
  double area = 0;
  for (int i = 0; i < body_.m_faces.size(); ++i) {
    const Face& face = body_.m_faces[i];
    const auto& ids = expected[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k)
      if (face.m_n[k] != &body_.m_nodes[bullet_index(ids[static_cast<std::size_t>(k)])])
        fail("face " + std::to_string(i) + ": not over the committed cut's nodes");
    const btVector3 a = record(ids[0]).rest_position(), b = record(ids[1]).rest_position(),
                    c = record(ids[2]).rest_position();
    if (!(rest_turn(a, b, c) < 0)) fail("face " + std::to_string(i) + ": folded over or flat at rest");
    area += 0.5 * static_cast<double>(face.m_ra);
  }
  const NetSpec& spec = net_->spec();
  const double net_area = spec.size_x * spec.size_z;
  if (std::abs(area - net_area) > 1e-4 * net_area)
    fail("faces cover " + std::to_string(area) + " m^2 at rest, the net " + std::to_string(net_area));
}

}  // namespace tcsb
