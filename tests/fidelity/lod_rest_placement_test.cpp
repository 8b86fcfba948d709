// Where a level's nodes rest, and what mass they carry: whole level-1 cuts of the converged suite's nets, with the
// blocks resting at their centroids (today's LodTree) or on their first leaves (RestPlacement::kVertex, every whole
// cut of a (2^k m + 1)-wide net an evenly spaced sub-grid of the leaves), each with the tree's masses (a block's
// leaves' sum) or with the leaves' masses spread over the level's nodes by the weights of bilinear interpolation
// between them (as a lumped finite-element mass matrix would). The calibration's own measurement (tcsb calibrate:
// the suite's world, steps and TC-SB settings, the reconstructed surface against full-resolution plain Bullet),
// each variant at its own fitted level-1 stiffness (docs/investigations/lod-rest-placement.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "analysis/fidelity_metrics.h"
#include "fidelity/calibration.h"
#include "fidelity/reconstruction.h"
#include "scene/scene_world.h"
#include "softbody/plain_softbody.h"
#include "softbody/tc_softbody.h"
#include "suite/suite.h"

namespace tcsb {
namespace {

const std::filesystem::path kSourceDir = TCSB_SOURCE_DIR;

enum class Masses { kTree, kInterpolated };

/// Each leaf's share of the level's nodes along one axis: leaf j between the nodes resting at leaf coordinates
/// p[a] <= j <= p[a + 1] gives (p[a + 1] - j) / (p[a + 1] - p[a]) of its mass to node a and the rest to a + 1.
std::vector<double> interpolation_weights(const std::vector<double>& p, int leaves) {
  std::vector<double> w(p.size(), 0.0);
  std::size_t a = 0;
  for (int j = 0; j < leaves; ++j) {
    while (a + 2 < p.size() && p[a + 1] <= j) ++a;
    const double t = (j - p[a]) / (p[a + 1] - p[a]);
    w[a] += 1 - t;
    w[a + 1] += t;
  }
  return w;
}

/// Gives the whole level-`level` cut of `body` the interpolated masses: node (gx, gy) carries the leaf mass times
/// its weight along x times its weight along z (the leaves' masses are equal). Writes Bullet's inverse masses and
/// link constants directly (no operation follows), the total unchanged.
void interpolate_masses(TcSoftBody& body, const Net& net, int level) {
  const LodTree& tree = net.lod();
  const int lw = tree.level_width(level), lh = tree.level_height(level);
  std::vector<double> px(static_cast<std::size_t>(lw)), pz(static_cast<std::size_t>(lh));
  const double sx = net.spec().size_x / (net.width() - 1), sz = net.spec().size_z / (net.height() - 1);
  for (int g = 0; g < lw; ++g)
    px[static_cast<std::size_t>(g)] = (tree.rest(tree.at(level, g, 0)).x() + 0.5 * net.spec().size_x) / sx;
  for (int g = 0; g < lh; ++g)
    pz[static_cast<std::size_t>(g)] = (tree.rest(tree.at(level, 0, g)).z() + 0.5 * net.spec().size_z) / sz;
  const std::vector<double> wx = interpolation_weights(px, net.width()), wz = interpolation_weights(pz, net.height());
  for (int i = 0; i < body.node_count(); ++i) {
    const LodNode& n = tree.node(body.tree_id(i));
    ASSERT_EQ(n.level, level);
    btSoftBody::Node& node = body.m_nodes[i];
    if (node.m_im == 0) continue;  // pinned
    const double m = net.spec().node_mass() * wx[static_cast<std::size_t>(n.gx)] * wz[static_cast<std::size_t>(n.gy)];
    node.m_im = static_cast<btScalar>(1.0 / m);
  }
  for (int l = 0; l < body.m_links.size(); ++l) {
    btSoftBody::Link& k = body.m_links[l];
    k.m_c0 = (k.m_n[0]->m_im + k.m_n[1]->m_im) / k.m_material->m_kLST;
  }
}

/// Mean over the measured steps of the RMS distance (% of the extent) of a whole level-1 cut from the reference, as
/// tcsb calibrate measures it (fidelity/calibration.cpp, level_error).
double level_one_error(const Suite& suite, const NetSpec& spec, RestPlacement rest, Masses masses, double k,
                       const std::vector<std::vector<Eigen::Vector3d>>& reference) {
  const auto net = std::make_shared<const Net>(spec, rest);
  SceneWorld world(suite.world, suite.scene);
  TcSettings tc = suite.tcsb;
  tc.level_stiffness = {k};
  TcSoftBody body(world.info(), net, suite.solver, tc);
  body.coarsen_to_level(1);
  if (masses == Masses::kInterpolated) interpolate_masses(body, *net, 1);
  const SceneWorld::Attachment attachment = world.attach(body);
  std::vector<Eigen::Vector3d> surface;
  double sum = 0;
  for (int s = 0; s < suite.warmup_steps + suite.steps; ++s) {
    world.step(static_cast<btScalar>(suite.world.dt));
    if (s < suite.warmup_steps) continue;
    reconstruct_leaves(body, surface);
    sum +=
        100.0 / net->extent() * surface_error(surface, reference[static_cast<std::size_t>(s - suite.warmup_steps)]).rms;
  }
  return sum / suite.steps;
}

std::vector<std::vector<Eigen::Vector3d>> reference_frames(const Suite& suite, const Net& net) {
  SceneWorld world(suite.world, suite.scene);
  std::unique_ptr<btSoftBody> body = make_plain_softbody(world.info(), net, suite.solver);
  const SceneWorld::Attachment attachment = world.attach(*body);
  std::vector<std::vector<Eigen::Vector3d>> frames;
  std::vector<Eigen::Vector3d> x;
  for (int s = 0; s < suite.warmup_steps + suite.steps; ++s) {
    world.step(static_cast<btScalar>(suite.world.dt));
    if (s < suite.warmup_steps) continue;
    copy_positions(*body, x);
    // The calibration keeps the reference as floats; so does this (the figures then match its own).
    for (Eigen::Vector3d& p : x) p = p.cast<float>().cast<double>();
    frames.push_back(x);
  }
  return frames;
}

// The table of docs/investigations/lod-rest-placement.md (a few minutes): run with
//   build/tests_fidelity --gtest_also_run_disabled_tests --gtest_filter='LodRestPlacement.DISABLED_*'
TEST(LodRestPlacement, DISABLED_WholeLevelOneCutsOfTheConvergedNets) {
  const Suite suite = parse_suite(kSourceDir / "suites" / "converged.json");
  struct Variant {
    const char* name;
    RestPlacement rest;
    Masses masses;
    double k;  // its fitted level-1 stiffness (tcsb calibrate with the variant, 2026-12-01)
  };
  const std::vector<Variant> variants = {
      {"centroid rest, tree masses (today)", RestPlacement::kCentroid, Masses::kTree, 0.4323772094142622},
      {"vertex rest, tree masses", RestPlacement::kVertex, Masses::kTree, 0.4307357098256527},
      {"centroid rest, interpolated masses", RestPlacement::kCentroid, Masses::kInterpolated, 0.4307357098256527},
      {"vertex rest, interpolated masses", RestPlacement::kVertex, Masses::kInterpolated, 0.42378220598326466},
  };
  std::vector<std::vector<double>> rms(variants.size());
  for (const NetSpec& spec : suite.nets) {
    const Net net(spec);
    const auto reference = reference_frames(suite, net);
    for (std::size_t v = 0; v < variants.size(); ++v)
      rms[v].push_back(level_one_error(suite, spec, variants[v].rest, variants[v].masses, variants[v].k, reference));
  }
  std::printf("| level-1 cut | kLST |");
  for (const NetSpec& spec : suite.nets) std::printf(" %s |", spec.name.c_str());
  std::printf(" mean |\n|---|---|");
  for (std::size_t n = 0; n <= suite.nets.size(); ++n) std::printf("---|");
  std::printf("\n");
  for (std::size_t v = 0; v < variants.size(); ++v) {
    double sum = 0;
    std::printf("| %s | %.3f |", variants[v].name, variants[v].k);
    for (const double e : rms[v]) {
      std::printf(" %.3f |", e);
      sum += e;
    }
    std::printf(" %.3f |\n", sum / static_cast<double>(rms[v].size()));
  }
}

}  // namespace
}  // namespace tcsb
