#include "softbody/bullet_setup.h"

#include <algorithm>
#include <numeric>
#include <random>

#include "softbody/vector_conversion.h"

namespace tcsb {

void apply_solver_settings(btSoftBody& body, const SolverSettings& settings) {
  body.m_cfg.piterations = settings.piterations;
  body.m_cfg.viterations = settings.viterations;
  body.m_cfg.diterations = settings.diterations;
  body.m_cfg.kDP = static_cast<btScalar>(settings.damping);
  body.m_cfg.collisions = 0;
  body.m_materials[0]->m_kLST = static_cast<btScalar>(settings.linear_stiffness);
}

void init_net_nodes(btSoftBody& body, const Net& net, int capacity) {
  const int n = static_cast<int>(net.node_count());
  if (capacity > n) body.m_nodes.reserve(capacity);
  body.m_nodes.resize(n, zeroed<btSoftBody::Node>());
  body.m_X.resize(n);
  for (int i = 0; i < n; ++i) {
    btSoftBody::Node& node = body.m_nodes[i];
    const Eigen::Vector3d& r = net.rest_positions()[static_cast<std::size_t>(i)];
    node.m_x = to_bullet(r);
    node.m_q = node.m_x;
    const btScalar mass = net.pinned()[static_cast<std::size_t>(i)]
                              ? btScalar(0)
                              : static_cast<btScalar>(net.masses()[static_cast<std::size_t>(i)]);
    node.m_im = mass > 0 ? 1 / mass : 0;
    node.m_material = body.m_materials[0];
    body.m_X[i] = node.m_x;
  }
  std::vector<std::int32_t> order;
  insert_node_leaves(body, order);
  body.updateBounds();
}

void insert_node_leaves(btSoftBody& body, std::vector<std::int32_t>& order) {
  order.resize(static_cast<std::size_t>(body.m_nodes.size()));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(20111219));  // fixed: every body gets the same tree
  // The box btSoftBody::predictMotion's btDbvt::update gives a node it re-inserts: the node and the margin, grown by
  // the update margin and stretched by the velocity over three steps (m_sst holds the last step's margins, all zero
  // before the first step, which leaves the node and the margin). A bare box inserted mid-fall would be left by every
  // moving node on the next step, and re-inserting them all would cost a second build.
  const btScalar margin = body.getCollisionShape()->getMargin();
  const btVector3 grow(body.m_sst.updmrg, body.m_sst.updmrg, body.m_sst.updmrg);
  for (const std::int32_t i : order) {
    btSoftBody::Node& node = body.m_nodes[i];
    btDbvtVolume box = btDbvtVolume::FromCR(node.m_x, margin);
    box.Expand(grow);
    box.SignedExpand(node.m_v * body.m_sst.velmrg);
    node.m_leaf = body.m_ndbvt.insert(box, &node);
  }
}

void append_net_links(btSoftBody& body, const Net& net) {
  body.m_links.reserve(static_cast<int>(net.links().size()));
  for (const NetLink& l : net.links()) body.appendLink(l.a, l.b, nullptr, false);
  body.updateConstants();
  body.m_bUpdateRtCst = false;
}

void append_face(btSoftBody& body, int a, int b, int c) {
  btSoftBody::Face& face = body.m_faces.expandNonInitializing();
  face = zeroed<btSoftBody::Face>();
  face.m_material = body.m_materials[0];
  face.m_n[0] = &body.m_nodes[a];
  face.m_n[1] = &body.m_nodes[b];
  face.m_n[2] = &body.m_nodes[c];
}

void append_cell_faces(btSoftBody& body) {
  const int n = body.m_nodes.size();
  const btSoftBody::Node* const base = n > 0 ? &body.m_nodes[0] : nullptr;
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(n));
  for (int li = 0; li < body.m_links.size(); ++li) {
    const auto a = static_cast<int>(body.m_links[li].m_n[0] - base);
    const auto b = static_cast<int>(body.m_links[li].m_n[1] - base);
    neighbours[static_cast<std::size_t>(a)].push_back(b);
    neighbours[static_cast<std::size_t>(b)].push_back(a);
  }
  for (auto& list : neighbours) std::sort(list.begin(), list.end());
  for (int i = 0; i < n; ++i) {
    const std::vector<int>& around = neighbours[static_cast<std::size_t>(i)];
    // The two later neighbours: on a row-major grid the next node along x, then the one along z.
    std::vector<int> later;
    for (const int k : around)
      if (k > i) later.push_back(k);
    if (later.size() < 2) continue;
    const int a = later[0], b = later[1];
    const std::vector<int>& na = neighbours[static_cast<std::size_t>(a)];
    const std::vector<int>& nb = neighbours[static_cast<std::size_t>(b)];
    int closing = -1;  // the cell's fourth node
    for (const int k : na)
      if (k != i && std::binary_search(nb.begin(), nb.end(), k)) closing = k;
    if (closing < 0) continue;
    append_face(body, i, a, closing);
    append_face(body, i, closing, b);
  }
  body.updateArea();
  body.updateNormals();
}

}  // namespace tcsb
