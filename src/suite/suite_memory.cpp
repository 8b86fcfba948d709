#include "suite/suite_memory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "net/net.h"
#include "suite/case_plan.h"
#include "suite/fidelity_plan.h"
#include "suite/scene_bodies.h"
#include "suite/suite_axes.h"
#include "suite/world_plan.h"

namespace tcsb {
namespace {

// Per-element memory, deliberately on the high side (sizes measured with sizeof on Bullet 3.24, single precision):
//  - a Bullet node: btSoftBody::Node 256 B, its rest position in btSoftBody::m_X 16 B, and its DBVT leaf and share
//    of inner nodes, 2 tree nodes of 96 B each: btDbvtNode is 56 B, but btAlignedAlloc(56, 16) asks malloc for
//    56 + 8 (the pointer it keeps to free) + 15 (alignment slack) = 79 B, a 96 B glibc chunk with its 8 B header.
//    (The model had 2 x 64 B and no m_X, 80 B/node too few: plain-only runs measured 11-13 % above it.)
//  - a Bullet link: btSoftBody::Link 72 B;
//  - a Bullet face (CreatePatch makes 2 per cell, bullet_patch only): btSoftBody::Face 144 B + 2 x 96 B of tree;
//  - in a windy scene every body's faces (scene.wind: 2 per cell, a TC-SB body reserving its finest cut's): Face
//    144 B, no tree (faces get DBVT leaves only with face collisions), and TC-SB's rebuild scratch (12 B per face,
//    4 B per leaf: 14 B per face);
//  - our Net: ~ 48 B per node (rest position, mass, pin flag, padding) + 12 B per link (NetLink);
//  - the LOD tree: ~ 4/3 N tree nodes x 116 B (LodNode 64 B, centroid and rest 2 x 24 B, spatial rank 4 B);
//  - a TC-SB body: Bullet nodes reserved for all 4/3 N tree nodes, ~ 200 B of bookkeeping per tree node (cut
//    membership, incidence lists, feedback state, and restore_order's scratch: 4 B per tree node and 2 x 4 B per
//    simulated node or link; about 110 B in all, plus the scratch), and Bullet links for up to 3 L;
//  - under the compliant material, every body's small steps on double positions (SubstepPositions: two 24 B
//    vectors and an 8 B inverse mass per simulated node; a TC-SB body's grow to its simulated nodes, at most the
//    tree's);
//  - the recorder: 36 B per step (StepSeries in run_result.h: three doubles, three int32, reserved to size by the
//    runner), counted for every step (warm-up included, a margin) of every run of the suite, all kept to the end.
constexpr double kDbvtNodeBytes = 96;
constexpr double kBulletNodeBytes = 256 + 16 + 2 * kDbvtNodeBytes;
constexpr double kBulletLinkBytes = 72;
constexpr double kBulletFaceBytes = 144 + 2 * kDbvtNodeBytes;
constexpr double kWindFaceBytes = 144 + 14;
constexpr double kNetNodeBytes = 48, kNetLinkBytes = 12;
constexpr double kTreeNodeBytes = 116, kTreeNodesPerLeaf = 4.0 / 3.0;
constexpr double kTcBookkeepingBytes = 200, kTcLinkFactor = 3;
constexpr double kSampleBytes = 3 * 8 + 3 * 4;
constexpr double kSubstepNodeBytes = 2 * 24 + 8;
constexpr double kPointBytes = 24;  // a grid point of a reconstructed surface: Eigen::Vector3d
// A world-pass track's copies of its bodies' grid points: the surfaces after the last step, the gathered scene, and
// the jump's "after" at a change (world_runner.cpp).
constexpr double kWorldSurfaceCopies = 3;
// A geomorphed TC-SB surface's recorded jumps (fidelity/surface_morph.h): a leaf index and its offset, 4 + 24 B.
constexpr double kMorphLeafBytes = 4 + 24;

// A scene with colliders gives every body a btSoftRigidDynamicsWorld of its own (scene/scene_world.h). Measured with
// mallinfo2 (uordblks + hblkhd) on Bullet 3.24: 4 672 144 B for the world, nearly all of it its collision
// configuration's pools (4096 persistent manifolds of 880 B, 4096 collision algorithms), filled when it is built.
constexpr double kCollisionWorldBytes = 4.7e6;
// And the world's sparse signed-distance field (btSoftBodyWorldInfo::m_sparsesdf, a btSparseSdf<3>): a hash table
// of 2383 cell pointers, and cells of 3 x 3 x 3 voxels of scene.sdf_voxel, each a Cell of 296 B (its 4^3 distances
// and links; a 304 B chunk with malloc's header), made on the first query of a point in them. A query is a node near
// a collider asking for its distance, in the collider's own frame: so a collider's cells lie in its bounding box
// there, whatever path it takes. Bullet keeps at most 256 x 1024 cells per world (Initialize's clampCells: beyond
// them it frees them all and begins again); GarbageCollect frees cells unused for 256 steps, which bounds nothing.
constexpr double kSdfTableBytes = 2383 * 8, kSdfCellBytes = 304, kSdfMaxCells = 256.0 * 1024, kSdfCellVoxels = 3;

/// Half extents of the region, in the collider's own frame, where nodes may ask for its distance: its bounding box
/// where it does not turn; where it does (a dynamic body, a tilted plane's slab), the cube around the ball that holds
/// its bounding box in any orientation. `pad`: how far beyond its surface a node may ask (the contact margins).
std::array<double, 3> sdf_query_half_extents(const Collider& c, double pad) {
  std::array<double, 3> half{};
  bool turns = c.motion == ColliderMotion::kDynamic;
  switch (c.shape) {
    case ColliderShape::kSphere: half = {c.radius, c.radius, c.radius}; break;
    case ColliderShape::kBox: half = c.half_extents; break;
    case ColliderShape::kPlane:
      half = {kPlaneSlabHalfWidth, kPlaneSlabHalfThickness, kPlaneSlabHalfWidth};
      turns = turns || !(c.normal[1] > 1 - 1e-6);  // the slab is turned from +y to the normal (scene_world.cpp)
      break;
  }
  for (double& h : half) h += pad;
  if (turns) {
    const double ball = std::sqrt(3.0) * std::sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]);
    half = {ball, ball, ball};
  }
  return half;
}

/// One net's bytes: what its cases share (the net and its LOD tree) and one body of each kind.
struct NetBytes {
  double shared = 0;
  double plain = 0;
  double tcsb = 0;
};

NetBytes net_bytes(const Suite& suite, const NetSpec& spec) {
  const double n = static_cast<double>(spec.node_count());
  const double l = static_cast<double>(expected_link_count(spec));
  const double tree = kTreeNodesPerLeaf * n;
  const double faces = suite.scene.wind ? 2.0 * (spec.width - 1) * (spec.height - 1) * kWindFaceBytes : 0.0;
  const double world = scene_world_bytes(suite.scene);  // every body has a world of its own
  const double substeps = suite.solver.compliant_model() ? kSubstepNodeBytes : 0.0;
  NetBytes b;
  b.plain = n * (kBulletNodeBytes + substeps) + l * kBulletLinkBytes + faces + world;
  b.tcsb =
      tree * (kBulletNodeBytes + kTcBookkeepingBytes + substeps) + kTcLinkFactor * l * kBulletLinkBytes + faces + world;
  b.shared = n * kNetNodeBytes + l * kNetLinkBytes + tree * kTreeNodeBytes;
  return b;
}

/// What a TC-SB body's geomorph (fidelity/surface_morph.h) may hold: a jump a boundary for as many boundaries as it
/// spreads each, every one over every leaf of the net.
double morph_bytes(const Suite& suite, const NetSpec& spec) {
  const int boundaries = suite.fidelity.geomorph_boundaries.value_or(suite.tcsb.blend_steps + 1);
  return boundaries * static_cast<double>(spec.node_count()) * kMorphLeafBytes;
}

/// Peak bytes of the world pass (world/world_runner.h), which runs after the cases: every track's bodies alive at
/// once (world_tracks), each body with a net of its own, and per track the surfaces it reconstructs, compares and
/// keeps for popping (kWorldSurfaceCopies of every body's grid points), with the reference's block of them, and every
/// TC-SB body's geomorph.
double world_peak_bytes(const Suite& suite) {
  const WorldTracks tracks = world_tracks(suite);
  if (tracks.tcsb + tracks.plain == 0) return 0;
  // Every body is of the first body's net (the suite's reader refuses others).
  const NetSpec* spec = net_named(suite, suite.scene.bodies.front().net);
  if (!spec) return 0;
  const NetBytes b = net_bytes(suite, *spec);
  const double bodies = static_cast<double>(suite.scene.bodies.size());
  const double points = bodies * static_cast<double>(spec->node_count());
  const double surfaces = (tracks.tcsb + tracks.plain) * kWorldSurfaceCopies * points * kPointBytes +
                          kWorldBlockSteps * points * (kPointBytes + 1);  // the reference's block, with its mask
  return bodies * (b.shared + tracks.tcsb * (b.tcsb + morph_bytes(suite, *spec)) + tracks.plain * b.plain) + surfaces;
}

/// Peak bytes while cases of net `spec` run: the shared net, one body per method (per case side by side); or, in the
/// fidelity pass, which runs afterwards, the reference and every subject at once (each counted as a TC-SB body, the
/// largest kind).
double net_peak_bytes(const Suite& suite, const NetSpec& spec) {
  const NetBytes b = net_bytes(suite, spec);
  const double shared = b.shared, plain = b.plain, tcsb_body = b.tcsb;
  double bytes = shared;
  const auto body_bytes = [&](Method m) {
    switch (m) {
      case Method::kPlain: return plain;
      case Method::kStock: return plain;
      case Method::kPlainEqual: return plain;  // a coarser grid of the same net: at most the plain body
      case Method::kBulletPatch: return plain + 2.0 * (spec.width - 1) * (spec.height - 1) * kBulletFaceBytes;
      case Method::kTcsb: return tcsb_body;
    }
    return tcsb_body;
  };
  if (suite.interleave_steps > 0) {
    // Side by side: every case of the net (each budget, each configuration) has its body alive at once.
    for (const CaseKey& key : expand_cases(suite))
      if (suite.nets[key.net].name == spec.name) bytes += body_bytes(key.method);
  } else {
    for (const Method m : suite.methods) bytes += body_bytes(m);
  }
  const bool has_tcsb = std::find(suite.methods.begin(), suite.methods.end(), Method::kTcsb) != suite.methods.end();
  const double subjects = has_tcsb ? static_cast<double>(fidelity_plan(suite).size()) : 0.0;
  const double fidelity = shared + plain + subjects * (tcsb_body + morph_bytes(suite, spec));
  return subjects > 0 ? std::max(bytes, fidelity) : bytes;
}

}  // namespace

double sdf_cells(const SceneSettings& scene) {
  if (!scene.has_colliders() || !scene.rigid_contact) return 0;  // no contact: nothing asks the field
  const double cell = kSdfCellVoxels * scene.sdf_voxel;
  // A node's box in the tree may reach a margin beyond it, and the collider's is widened by the margin again
  // (btSoftBody's CollideSDF_RS); a cell more on either side for the grid's alignment.
  const double pad = 2 * scene.margin;
  double cells = 0;
  for (const Collider& c : scene.colliders) {
    double product = 1;
    for (const double h : sdf_query_half_extents(c, pad)) product *= std::ceil(2 * h / cell) + 2;
    cells += product;
  }
  return std::min(cells, kSdfMaxCells);
}

double scene_world_bytes(const SceneSettings& scene) {
  if (!scene.has_colliders()) return 0;  // stepped solo: no world, no field
  return kCollisionWorldBytes + kSdfTableBytes + sdf_cells(scene) * kSdfCellBytes;
}

double recorder_peak_bytes(const Suite& suite) {
  const std::vector<Suite> configurations = configuration_suites(suite);  // the axes may vary the steps
  double samples = 0;
  for (const CaseKey& key : expand_cases(suite)) {
    if (!runs_unit(suite, key.configuration, key.net)) continue;
    const Suite& settings = configurations[key.configuration];
    samples += static_cast<double>(settings.steps) + settings.warmup_steps;
  }
  return samples * suite.repetitions * kSampleBytes;
}

namespace {

std::size_t peak_net_index(const Suite& suite) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < suite.nets.size(); ++i) {
    if (!runs_net(suite, i)) continue;
    if (!best || net_peak_bytes(suite, suite.nets[i]) > net_peak_bytes(suite, suite.nets[*best])) best = i;
  }
  return best.value_or(0);
}

}  // namespace

std::string format_bytes(double bytes) {
  char buf[48];
  if (bytes >= 1024.0 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  else
    std::snprintf(buf, sizeof buf, "%.1f MiB", bytes / (1024.0 * 1024));
  return buf;
}

std::uint64_t estimate_peak_bytes(const Suite& suite) {
  // One net's cases at a time, or every net's at once (interleave_across_nets: counted as the sum of the nets'
  // peaks, which also adds up their fidelity passes, run one net at a time; on the high side, as everything here).
  double peak = 0;
  for (std::size_t i = 0; i < suite.nets.size(); ++i) {
    if (!runs_net(suite, i)) continue;
    const double net = net_peak_bytes(suite, suite.nets[i]);
    peak = suite.interleave_across_nets ? peak + net : std::max(peak, net);
  }
  peak = std::max(peak, world_peak_bytes(suite));  // the world pass runs after the cases, alone
  const double bytes = std::ceil(peak + recorder_peak_bytes(suite));
  constexpr double kMax = 1.8e19;  // just under 2^64: saturate rather than overflow
  return bytes >= kMax ? std::numeric_limits<std::uint64_t>::max() : static_cast<std::uint64_t>(bytes);
}

std::optional<MemoryShortfall> memory_shortfall(const Suite& suite, const std::vector<MemoryHeadroom>& headrooms) {
  const std::optional<MemoryHeadroom> smallest = smallest_headroom(headrooms);
  bool runs_any = false;
  for (std::size_t i = 0; i < suite.nets.size(); ++i) runs_any = runs_any || runs_net(suite, i);
  if (!smallest || !runs_any) return std::nullopt;
  MemoryShortfall s;
  s.needed = static_cast<double>(estimate_peak_bytes(suite));
  s.headroom = *smallest;
  s.usable = 0.8 * static_cast<double>(smallest->bytes);
  if (s.needed <= s.usable) return std::nullopt;
  s.net = peak_net_index(suite);
  s.recorder = recorder_peak_bytes(suite) > net_peak_bytes(suite, suite.nets[s.net]);
  return s;
}

std::optional<MemoryShortfall> memory_shortfall(const Suite& suite) {
  return memory_shortfall(suite, memory_headrooms());
}

}  // namespace tcsb
