// The shared recipe that turns a Net's finest level into Bullet nodes and links. The plain baseline and TC-SB both
// start from it, so with no operations they are the same body, link for link.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "../net/net.h"
#include "../softbody/solver_settings.h"

namespace tcsb {

/// A Bullet node or link with every byte zero: what Bullet's ZeroInitialize makes before it fills in fields.
template <class T>
T zeroed() {
  T value;
  std::memset(static_cast<void*>(&value), 0, sizeof(T));
  return value;
}

/// Bullet's solver configuration for every body of a run: the suite's iterations, damping and stiffness, and
/// collisions off (the paper's tests run none; Bullet then runs no collision code at all when stepped solo).
void apply_solver_settings(btSoftBody& body, const SolverSettings& settings);

/// Fills a body made with btSoftBody(worldInfo, 0, nullptr, nullptr) with the net's leaves as nodes, exactly as
/// Bullet's node-array constructor would (zeroed node, position, previous position, inverse mass — pinned leaves
/// get 0 —, default material), except for one thing: the nodes' DBVT leaves are inserted in a fixed shuffled
/// order. Bullet inserts them in array order, and a row-major grid inserted in order degenerates its tree into a
/// chain (depth 2W: 513 at 257x257), which costs 10x at build time and ~30% per step (DBVT re-insertions walk
/// from the root). `capacity` reserves the node array first (TC-SB reserves its whole tree).
void init_net_nodes(btSoftBody& body, const Net& net, int capacity = 0);

/// Inserts every node's leaf into the body's (empty) node DBVT, as init_net_nodes and TcSoftBody::rebuild_node_dbvt
/// build it: in a fixed shuffle of the node indices, the same for every body of as many nodes (`order` is scratch
/// that keeps it), each leaf with the box Bullet's own update would give the node now (before the first step: its
/// position and the margin).
void insert_node_leaves(btSoftBody& body, std::vector<std::int32_t>& order);

/// Appends the net's links in canonical order with stock appendLink(), then lets Bullet compute every link
/// constant once, at rest (updateConstants), and clears the dirty flag so no later step redoes it (docs/design.md,
/// "Link constants and the m_bUpdateRtCst trap").
void append_net_links(btSoftBody& body, const Net& net);

/// Appends a face over nodes a, b and c as btSoftBody::appendFace(a, b, c) does (a zeroed face of the default
/// material), except that it leaves m_bUpdateRtCst alone: appendFace sets it, and the next step would then reset
/// every link's rest length to its length at that moment. The face's area (m_ra) is the caller's to set.
void append_face(btSoftBody& body, int a, int b, int c);

/// Gives a body whose links form a grid of quads (a plain body of a net with structural links only, CreatePatch's
/// grid, a uniform grid) the faces of its cells: for each node, the cell closed by its two later neighbours and
/// their common neighbour, split from the node along the cell's diagonal into two triangles — on a row-major grid
/// the cells in row-major order, each split as TcSoftBody::enable_faces() splits it on the finest cut. Then Bullet's
/// face and node areas (updateArea, from the positions now: a body's rest shape when it is fresh) and normals. The
/// aerodynamic model reads them; nothing else a compared body does touches faces. O(L).
void append_cell_faces(btSoftBody& body);

/// One step exactly as btSoftRigidDynamicsWorld would do it for a lone body without collisions (docs/design.md,
/// "One step").
inline void step_soft_body(btSoftBody& body, btScalar dt) {
  body.predictMotion(dt);
  body.solveConstraints();
  body.integrateMotion();
}

}  // namespace tcsb
