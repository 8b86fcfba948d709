// TcSoftBody's masses that follow the cut (TcSettings::masses = Masses::kCut; docs/design.md, "Masses that follow
// the cut"). A block's node rests on its first leaf; each of its leaves is shared between that node and the nodes at
// the block's three far corners by the bilinear weights between them, as a lumped finite-element mass matrix shares
// it. A far corner that falls on no node of the cut (it hangs on a coarser block's side, or lies past the net) leaves
// its share with the block's own node, so the shares always sum to the net's mass.
#include <array>
#include <stdexcept>

#include "softbody/tc_softbody_impl.h"
#include "softbody/vector_conversion.h"

namespace tcsb {

namespace {
/// The bilinear weight towards the next node along one axis of a leaf at `at`, in a block whose node rests at `rest`
/// and whose next node along that axis rests at `next` (-1: none). Leaves before the rest (a block resting on a
/// pinned leaf inside it, or on the net's last row) stay with the node.
double toward_next(int at, int rest, int next) {
  return next >= 0 && at > rest ? static_cast<double>(at - rest) / static_cast<double>(next - rest) : 0.0;
}
}  // namespace

void TcSoftBody::Impl::build_corner_shares() {
  const LodTree& lod = tree();
  if (lod.placement() != RestPlacement::kVertex)
    throw std::invalid_argument(
        "TcSoftBody: masses that follow the cut need blocks resting on their first leaf (RestPlacement::kVertex)");
  const int width = lod.level_width(0), height = lod.level_height(0);
  corner_shares_.assign(lod.size(), CornerShares{});
  for (std::size_t id = 0; id < lod.size(); ++id) {
    const LodNode& n = lod.nodes()[id];
    CornerShares& c = corner_shares_[id];
    const LodNode& rest_leaf = lod.node(tree().rest_leaf(static_cast<TreeId>(id)));
    c.x = rest_leaf.gx;
    c.z = rest_leaf.gy;
    c.next_x = n.leaf_x1 < width ? n.leaf_x1 : -1;
    c.next_z = n.leaf_y1 < height ? n.leaf_y1 : -1;
    for (int z = n.leaf_y0; z < n.leaf_y1; ++z) {
      const double v = toward_next(z, c.z, c.next_z);
      for (int x = n.leaf_x0; x < n.leaf_x1; ++x) {
        const double u = toward_next(x, c.x, c.next_x);
        const double m = lod.node(lod.at(0, x, z)).mass;
        c.share[0] += m * (1 - u) * (1 - v);
        c.share[1] += m * u * (1 - v);
        c.share[2] += m * (1 - u) * v;
        c.share[3] += m * u * v;
      }
    }
  }
}

TreeId TcSoftBody::Impl::holding(int x, int z, bool committed) const { return holders(x, z)[committed ? 0 : 1]; }

std::array<TreeId, 2> TcSoftBody::Impl::holders(int x, int z) const {
  // (each cut covers every leaf, so both are found below the root; while no operation blends they are one node)
  std::array<TreeId, 2> found{kNoTreeNode, kNoTreeNode};  // the committed cut's, the old cut's
  for (TreeId id = tree().leaf_at(x, z); id != kNoTreeNode; id = tree().node(id).parent) {
    const CutState s = state(id);
    if (found[0] == kNoTreeNode && (s == CutState::kActive || s == CutState::kArriving)) found[0] = id;
    if (found[1] == kNoTreeNode && (s == CutState::kActive || s == CutState::kLeaving)) found[1] = id;
    if (found[0] != kNoTreeNode && found[1] != kNoTreeNode) break;
  }
  return found;
}

std::array<double, 2> TcSoftBody::Impl::cut_mass(TreeId id) const {
  const CutState s = state(id);
  const std::array<bool, 2> in{s == CutState::kActive || s == CutState::kArriving,
                               s == CutState::kActive || s == CutState::kLeaving};
  std::array<double, 2> mass{0, 0};
  if (!in[0] && !in[1]) return mass;
  const CornerShares& c = corner_shares_[static_cast<std::size_t>(id)];
  const auto rests_at = [&](TreeId node, int x, int z) {
    const CornerShares& o = corner_shares_[static_cast<std::size_t>(node)];
    return o.x == x && o.z == z;
  };
  // Each cut's mass gathers its terms in the same order; the two cuts share the climbs that find the holders.
  for (std::size_t cut = 0; cut < 2; ++cut)
    if (in[cut]) mass[cut] = c.share[0];
  // Its far corners: each share goes to the node resting there, or stays here when none does.
  const std::array<std::array<int, 2>, 3> corners{{{c.next_x, c.z}, {c.x, c.next_z}, {c.next_x, c.next_z}}};
  for (std::size_t k = 0; k < 3; ++k) {
    const double share = c.share[k + 1];
    if (share == 0) continue;  // (every share past the net is 0)
    const auto [x, z] = corners[k];
    const std::array<TreeId, 2> held = holders(x, z);
    for (std::size_t cut = 0; cut < 2; ++cut)
      if (in[cut] && !rests_at(held[cut], x, z)) mass[cut] += share;
  }
  // The blocks to its left, below and diagonally below-left hold the leaves just before its rest; it receives their
  // share when it rests on their far corner.
  const auto receive = [&](int x, int z, const auto& gives, std::size_t k) {
    const std::array<TreeId, 2> held = holders(x, z);
    for (std::size_t cut = 0; cut < 2; ++cut) {
      if (!in[cut]) continue;
      const CornerShares& b = corner_shares_[static_cast<std::size_t>(held[cut])];
      if (gives(b)) mass[cut] += b.share[k];
    }
  };
  if (c.x > 0)
    receive(
        c.x - 1, c.z, [&](const CornerShares& b) { return b.next_x == c.x && b.z == c.z; }, 1);
  if (c.z > 0)
    receive(
        c.x, c.z - 1, [&](const CornerShares& b) { return b.x == c.x && b.next_z == c.z; }, 2);
  if (c.x > 0 && c.z > 0)
    receive(
        c.x - 1, c.z - 1, [&](const CornerShares& b) { return b.next_x == c.x && b.next_z == c.z; }, 3);
  return mass;
}

const std::vector<TreeId>& TcSoftBody::Impl::ring_nodes(TreeId block) {
  std::vector<TreeId>& nodes = settle_scratch_;
  nodes.clear();
  const auto add = [&](TreeId id) {
    if (id == kNoTreeNode || bullet_[static_cast<std::size_t>(id)] < 0) return;
    for (TreeId n : nodes)
      if (n == id) return;
    nodes.push_back(id);
  };
  const LodNode& b = tree().node(block);
  add(block);
  for (int i = 0; i < b.child_count; ++i) add(b.children[static_cast<std::size_t>(i)]);
  // The ring of leaves around the block, in both cuts: every node whose corners or whose neighbours' corners the
  // operation can have moved holds one of them.
  // Along one side, neighbouring leaves mostly share their holders: a leaf before the ends of the blocks last found on
  // that side in both cuts is held by them again (a cut holds each leaf once, and the side runs along one row or
  // column), and adding them again would change nothing, so it is not looked up.
  const int width = tree().level_width(0), height = tree().level_height(0);
  const auto add_holders = [&](int x, int z, bool along_x, std::array<int, 2>& held_until) {
    if (x < 0 || z < 0 || x >= width || z >= height) return;
    const int at = along_x ? x : z;
    if (at < held_until[0] && at < held_until[1]) return;
    const std::array<TreeId, 2> held = holders(x, z);
    for (std::size_t cut = 0; cut < 2; ++cut) {
      add(held[cut]);
      if (held[cut] != kNoTreeNode)
        held_until[cut] = along_x ? tree().node(held[cut]).leaf_x1 : tree().node(held[cut]).leaf_y1;
    }
  };
  std::array<std::array<int, 2>, 4> sides{};  // below, above, left, right: the first leaf past each cut's holder
  for (int x = b.leaf_x0 - 1; x <= b.leaf_x1; ++x) {
    add_holders(x, b.leaf_y0 - 1, true, sides[0]);
    add_holders(x, b.leaf_y1, true, sides[1]);
  }
  for (int z = b.leaf_y0; z < b.leaf_y1; ++z) {
    add_holders(b.leaf_x0 - 1, z, false, sides[2]);
    add_holders(b.leaf_x1, z, false, sides[3]);
  }
  return nodes;
}

void TcSoftBody::Impl::settle_ring(TreeId block) {
  if (!cut_masses() && !vertex_edges()) return;  // (the paper's tree and masses: nothing around the block changes)
  const std::vector<TreeId>& nodes = ring_nodes(block);
  if (cut_masses()) settle_cut_masses(nodes);
  if (solver_.compliant_model())  // the cells beside the ring's links changed, and with them their compliance
    for (const TreeId id : nodes) refresh_incident_constants(id);
  if (!vertex_edges()) return;
  for (const TreeId id : nodes)
    for (const std::int32_t li : incidence_[static_cast<std::size_t>(id)]) {
      Material* m = edge_material(li);
      if (body_.m_links[li].m_material == m) continue;
      body_.m_links[li].m_material = m;
      refresh_link_constant(li);
    }
}

void TcSoftBody::Impl::settle_cut_masses(const std::vector<TreeId>& nodes) {
  // The mass that moves keeps its momentum: nodes that lose mass keep their velocity, and what they lose goes to the
  // nodes that gain, each in proportion to its gain (pinned nodes keep the pin's velocity whatever they gain).
  double gained = 0;
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  std::vector<double>& target = settle_targets_;
  target.resize(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const TreeId id = nodes[i];
    target[i] = target_mass(id);
    const double change = target[i] - record(id).sim_mass;
    if (change < 0) {
      momentum -= change * to_eigen(body_.m_nodes[record(id).bullet].m_v);
    } else if (change > 0 && !tree().node(id).pinned()) {
      gained += change;
    }
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const TreeId id = nodes[i];
    const double before = record(id).sim_mass, change = target[i] - before;
    if (change == 0) continue;
    if (change > 0 && gained > 0 && !tree().node(id).pinned()) {
      Node& n = body_.m_nodes[record(id).bullet];
      n.m_v = to_bullet((before * to_eigen(n.m_v) + (change / gained) * momentum) / target[i]);
    }
    set_simulated_mass(id, target[i]);
    refresh_incident_constants(id);
  }
}

}  // namespace tcsb
