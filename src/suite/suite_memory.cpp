#include "suite/suite_memory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "net/net.h"
#include "suite/case_plan.h"
#include "suite/fidelity_plan.h"
#include "suite/suite_axes.h"

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

/// Peak bytes while cases of net `spec` run: the shared net, one body per method (per case side by side); or, in the
/// fidelity pass, which runs afterwards, the reference and every subject at once (each counted as a TC-SB body, the
/// largest kind).
double net_peak_bytes(const Suite& suite, const NetSpec& spec) {
  const double n = static_cast<double>(spec.node_count());
  const double l = static_cast<double>(expected_link_count(spec));
  const double tree = kTreeNodesPerLeaf * n;
  const double faces = suite.scene.wind ? 2.0 * (spec.width - 1) * (spec.height - 1) * kWindFaceBytes : 0.0;
  const double plain = n * kBulletNodeBytes + l * kBulletLinkBytes + faces;
  const double tcsb_body =
      tree * (kBulletNodeBytes + kTcBookkeepingBytes) + kTcLinkFactor * l * kBulletLinkBytes + faces;
  const double shared = n * kNetNodeBytes + l * kNetLinkBytes + tree * kTreeNodeBytes;
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
  const double fidelity = shared + plain + subjects * tcsb_body;
  return subjects > 0 ? std::max(bytes, fidelity) : bytes;
}

}  // namespace

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
