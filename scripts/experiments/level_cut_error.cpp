// Experiment (not built by CMake; docs/methodology.md, "Why calibrated TC-SB errs more than the calibrated grid"):
// where a coarse TC-SB body's error comes from, on the first net of a suite. It steps the full-resolution reference,
// a TC-SB body coarsened to one level (link stiffness K for every level, or K,K2,K3 per level; with "half" only the
// blocks of the net's left half coarsen) and the uniform grid of a budget (stiffness KU) in lockstep and prints, as
// mean-over-measured-steps RMS in % of the extent:
//   floor: the level cut with every node put on the reference sampled (bilinearly over the leaf grid) at the
//          node's rest position, reconstructed (the reconstruction's own error); for a block resting at its centroid
//          that is its block's mean of the reference for level-1 blocks (2 x 2 or 1 x 2 leaves), and the mean of
//          its four central leaves for larger blocks; sim recon: the simulated cut, reconstructed (what the fidelity
//          pass measures); nodes-vs-sampled-at-rest: its nodes against those points (the body's own error);
//   and for the grid: bilinear floor, simulated, and its nodes against the reference sampled at them.
// "sort" reorders the cut's Bullet links row-major, as a plain grid has them (does link order matter?).
// Patterns of level-1 blocks in a cut that is otherwise at level 0 (LEVEL is then ignored; docs/methodology.md,
// "Interfaces between levels"): "checker" every other block, "icheck" / "bcheck" those of them away from / on the
// border, "interior" / "border" every block away from / on the border, "sparse" every third block along both axes
// (isolated blocks), "sqN" a centred square of N x N blocks, "csN" an N x N square in the corner at the origin,
// "file:PATH" the blocks marked '#' in a text file of one row of level-1 blocks per line (as feedback_freeze.patch's
// TCSB_EXP_MAP prints the feedback's cut). With LCE_DELAY=d and an "sqN" pattern the subject instead starts at full
// resolution like the reference and begins the square's coarsens at step d, blending one step per step as TC-SB does
// in the fidelity pass (a coarsen made while the cloth moves, against one made at rest).
// Build (after the Release build):
//   g++ -O2 -std=c++20 -DNDEBUG -I src -I build/generated -isystem /usr/include/eigen3 -isystem /usr/include/bullet \
//     scripts/experiments/level_cut_error.cpp -o /tmp/level_cut_error build/libtcsb_fidelity.a build/libtcsb_case.a \
//     build/libtcsb_suite.a build/libtcsb_analysis.a build/libtcsb_feedback.a build/libtcsb_softbody.a \
//     build/libtcsb_net.a build/libtcsb_base.a -lBulletSoftBody -lBulletDynamics -lBulletCollision -lLinearMath
//     -lpthread
// Every simulated node starts at its rest position. To try other rest positions of the coarse levels on code before
// blocks rested on the border (commit 94e0e8f), build with src/net/lod_tree.cpp patched by border_rest.patch added
// before the libraries, and set TCSB_EXP_BORDER=snap|vertex|lattice (that patch says what each does).
// Usage: level_cut_error SUITE LEVEL K[,K2,K3] BUDGET KU [sort|half|PATTERN]
#include "analysis/fidelity_metrics.h"
#include "case/case_body.h"
#include "fidelity/calibration.h"
#include "fidelity/fidelity_subject.h"
#include "fidelity/reconstruction.h"
#include "net/grid_resample.h"
#include "softbody/bullet_setup.h"
#include "softbody/plain_softbody.h"
#include "softbody/vector_conversion.h"
#include "suite/fidelity_plan.h"
#include "suite/suite.h"
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>
#include <vector>
using namespace tcsb;
int main(int argc, char** argv) {
  Suite suite = parse_suite(argv[1]);
  const int level = std::atoi(argv[2]);
  const double k = std::atof(argv[3]);            // TC-SB level stiffness for all levels >= 1 (or the first of a list)
  const double budget_frac = std::atof(argv[4]);  // uniform grid budget
  const double ku = std::atof(argv[5]);           // uniform grid stiffness
  auto net = std::make_shared<const Net>(suite.nets[0]);
  const double pct = 100.0 / net->extent();
  SoftBodyWorld wr(suite.world), wt(suite.world), wu(suite.world);
  auto ref = make_plain_softbody(wr, *net, suite.solver);
  TcSettings tc = suite.tcsb;
  if (k > 0) tc.level_stiffness = {k, k, k};
  // K may list one stiffness per level from level 1 on, comma-separated ("0.424,0.129,0.020"): the last holds above.
  if (const std::string ks = argv[3]; ks.find(',') != std::string::npos) {
    tc.level_stiffness.clear();
    for (std::size_t at = 0; at != std::string::npos;) {
      const std::size_t comma = ks.find(',', at);
      tc.level_stiffness.push_back(std::atof(ks.substr(at, comma == std::string::npos ? comma : comma - at).c_str()));
      at = comma == std::string::npos ? comma : comma + 1;
    }
  }
  TcSoftBody body(wt, net, suite.solver, tc);
  // "half": only the blocks of the net's left half (x below the middle) coarsen, to `level`; the right half stays at
  // level 0 (a cut of two levels, with one boundary between them down the middle).
  const bool half = argc > 6 && std::string(argv[6]) == "half";
  const std::string pattern = argc > 6 ? argv[6] : "";
  const auto coarsen = [&](TcSoftBody& b) {
    if (pattern == "checker" || pattern == "icheck" || pattern == "border" || pattern == "interior" ||
        pattern == "sparse" || pattern == "bcheck" || pattern.rfind("sq", 0) == 0 || pattern.rfind("cs", 0) == 0 ||
        pattern.rfind("file:", 0) == 0) {
      const LodTree& t = b.tree();
      for (bool began = true; began;) {  // rounds: a block cannot coarsen while its neighbour blends
        began = false;
        for (int gy = 0; gy < t.level_height(1); ++gy)
          for (int gx = 0; gx < t.level_width(1); ++gx) {
            const TreeId id = t.at(1, gx, gy);
            const bool onb = t.touches_border(t.node(id));
            bool want = false;
            if (pattern.rfind("sq", 0) == 0) {
              const int side = std::atoi(pattern.c_str() + 2);
              const int c0 = (t.level_width(1) - side) / 2;
              want = gx >= c0 && gx < c0 + side && gy >= c0 && gy < c0 + side;
            }
            if (pattern.rfind("cs", 0) == 0) {
              const int side = std::atoi(pattern.c_str() + 2);
              want = gx < side && gy < side;
            }
            if (pattern.rfind("file:", 0) == 0) {
              static std::vector<std::string> rows = [&] {
                std::vector<std::string> r;
                FILE* f = std::fopen(pattern.c_str() + 5, "r");
                char line[256];
                while (f && std::fgets(line, sizeof line, f)) r.emplace_back(line);
                if (f) std::fclose(f);
                return r;
              }();
              want =
                  gy < static_cast<int>(rows.size()) && gx < static_cast<int>(rows[gy].size()) && rows[gy][gx] == '#';
            }
            if (pattern == "checker") want = (gx + gy) % 2 == 0;
            if (pattern == "icheck") want = (gx + gy) % 2 == 0 && !onb;
            if (pattern == "bcheck") want = (gx + gy) % 2 == 0 && onb;
            if (pattern == "border") want = onb;
            if (pattern == "interior") want = !onb;
            if (pattern == "sparse") want = gx % 3 == 1 && gy % 3 == 1;
            if (want && b.can_coarsen(id).ok) {
              b.begin_coarse(id);
              began = true;
            }
          }
        while (b.interpolations() > 0) b.advance_blends();
      }
      return b.committed_count();
    }
    if (!half) return coarsen_to_level(b, level);
    const LodTree& t = b.tree();
    for (int l = 1; l <= level; ++l)
      for (bool began = true; began;) {
        began = false;
        for (int gy = 0; gy < t.level_height(l); ++gy)
          for (int gx = 0; gx < t.level_width(l); ++gx) {
            const TreeId id = t.at(l, gx, gy);
            if (2 * t.node(id).leaf_x1 <= net->width() + 1 && b.can_coarsen(id).ok) {
              b.begin_coarse(id);
              began = true;
            }
          }
        while (b.interpolations() > 0) b.advance_blends();
      }
    return b.committed_count();
  };
  // LCE_DELAY=d: the subject starts at full resolution and its pattern's coarsens begin at step d, blending one step
  // per step as the fidelity pass's TC-SB does (rounds of coarsens as the blends allow).
  const int delay = std::getenv("LCE_DELAY") ? std::atoi(std::getenv("LCE_DELAY")) : -1;
  if (delay < 0) coarsen(body);
  // Every simulated node starts at its rest position (the net starts at rest; a coarsened node would otherwise
  // start at its block's centre of mass, which differs from its rest position under TCSB_EXP_BORDER).
  const auto place_at_rest = [](TcSoftBody& b) {
    for (int i = 0; i < b.node_count(); ++i)
      b.m_nodes[i].m_x = b.m_nodes[i].m_q = to_bullet(b.tree().rest(b.tree_id(i)));
  };
  if (delay < 0) place_at_rest(body);
  if (argc > 6 && std::string(argv[6]) == "sort") {
    // Throwaway: Bullet's links in row-major order of their first endpoint (as a plain grid has them), horizontal
    // first.
    const btSoftBody::Node* first = &body.m_nodes[0];
    auto key = [&](const btSoftBody::Link& l) {
      const TreeId a = body.tree_id(static_cast<int>(l.m_n[0] - first)),
                   b = body.tree_id(static_cast<int>(l.m_n[1] - first));
      const LodNode& na = body.tree().node(a);
      const LodNode& nb = body.tree().node(b);
      const LodNode& lo = (na.leaf_y0 < nb.leaf_y0 || (na.leaf_y0 == nb.leaf_y0 && na.leaf_x0 < nb.leaf_x0)) ? na : nb;
      const bool vertical = na.leaf_y0 != nb.leaf_y0;
      return std::tuple(lo.leaf_y0, lo.leaf_x0, vertical);
    };
    std::vector<btSoftBody::Link> links(&body.m_links[0], &body.m_links[0] + body.m_links.size());
    std::stable_sort(links.begin(), links.end(), [&](const auto& x, const auto& y) { return key(x) < key(y); });
    for (int i = 0; i < body.m_links.size(); ++i) body.m_links[i] = links[static_cast<std::size_t>(i)];
  }
  // a static copy of the same cut for the "perfect nodes" floor
  SoftBodyWorld ws(suite.world);
  TcSoftBody still(ws, net, suite.solver, tc);
  coarsen(still);
  place_at_rest(still);
  const Net coarse(coarse_net_spec(net->spec(), node_budget(*net, budget_frac)));
  SolverSettings us = suite.solver;
  us.linear_stiffness = ku;
  auto uni = make_plain_softbody(wu, coarse, us);
  const LodTree& tree = net->lod();
  std::vector<Eigen::Vector3d> rx, leaves, ux, uleaves, sampled, blockmean(body.node_count()), nodes;
  double s_floor = 0, s_tc = 0, s_tcnode = 0, s_u = 0, s_ufloor = 0, s_unode = 0, s_left = 0, s_right = 0;
  int n = 0;
  for (int s = 0; s < suite.warmup_steps + suite.steps; ++s) {
    step_soft_body(*ref, suite.world.dt);
    if (delay >= 0 && s >= delay && pattern.rfind("sq", 0) == 0) {
      body.advance_blends();
      const LodTree& t = body.tree();
      const int side = std::atoi(pattern.c_str() + 2);
      const int c0 = (t.level_width(1) - side) / 2;
      for (int gy = c0; gy < c0 + side; ++gy)
        for (int gx = c0; gx < c0 + side; ++gx)
          if (body.can_coarsen(t.at(1, gx, gy)).ok) body.begin_coarse(t.at(1, gx, gy));
    }
    body.simulate_step(suite.world.dt);
    step_soft_body(*uni, suite.world.dt);
    if (s < suite.warmup_steps) continue;
    copy_positions(*ref, rx);
    // perfect nodes: each simulated node at the reference sampled (bilinearly over the leaf grid) at its rest
    // position, which for a block resting at its centroid is its block's mean of the reference (rest position if
    // pinned)
    const Eigen::Vector3d r00 = tree.rest(tree.at(0, 0, 0));
    const double du = (tree.rest(tree.at(0, net->width() - 1, 0)) - r00).x() / (net->width() - 1);
    const double dv = (tree.rest(tree.at(0, 0, net->height() - 1)) - r00).z() / (net->height() - 1);
    const auto sample = [&](const Eigen::Vector3d& r) {
      const double u = std::clamp((r.x() - r00.x()) / du, 0.0, net->width() - 1.0);
      const double v = std::clamp((r.z() - r00.z()) / dv, 0.0, net->height() - 1.0);
      const int x0 = std::min(static_cast<int>(u), net->width() - 2),
                y0 = std::min(static_cast<int>(v), net->height() - 2);
      const double fu = u - x0, fv = v - y0;
      return Eigen::Vector3d((1 - fu) * (1 - fv) * rx[tree.at(0, x0, y0)] + fu * (1 - fv) * rx[tree.at(0, x0 + 1, y0)] +
                             (1 - fu) * fv * rx[tree.at(0, x0, y0 + 1)] + fu * fv * rx[tree.at(0, x0 + 1, y0 + 1)]);
    };
    for (int i = 0; i < still.node_count(); ++i) {
      const TreeId id = still.tree_id(i);
      Eigen::Vector3d x = tree.node(id).pinned() ? tree.rest(id) : sample(tree.rest(id));
      if (tree.node(id).is_leaf()) x = rx[id];
      still.m_nodes[i].m_x = to_bullet(x);
    }
    reconstruct_leaves(still, leaves);
    s_floor += pct * surface_error(leaves, rx).rms;
    // the simulated level cut: its reconstruction, and its nodes against the block means
    reconstruct_leaves(body, leaves);
    s_tc += pct * surface_error(leaves, rx).rms;
    {  // the same RMS over the leaves of the net's left half (x < width / 2) and of its right half
      double l2 = 0, r2 = 0;
      int lc = 0, rc = 0;
      for (int y = 0; y < net->height(); ++y)
        for (int x = 0; x < net->width(); ++x) {
          const TreeId id = tree.at(0, x, y);
          const double e = (leaves[static_cast<std::size_t>(id)] - rx[static_cast<std::size_t>(id)]).squaredNorm();
          if (2 * x < net->width())
            l2 += e, ++lc;
          else
            r2 += e, ++rc;
        }
      s_left += pct * std::sqrt(l2 / lc);
      s_right += pct * std::sqrt(r2 / rc);
    }
    double e2 = 0;
    int cnt = 0;
    for (int i = 0; i < body.node_count(); ++i) {
      const TreeId id = body.tree_id(i);
      const Eigen::Vector3d target = to_eigen(still.m_nodes[still.bullet_index(id)].m_x);
      e2 += (to_eigen(body.m_nodes[i].m_x) - target).squaredNorm();
      ++cnt;
    }
    s_tcnode += pct * std::sqrt(e2 / cnt);
    // uniform grid: bilinear reconstruction; its floor; its nodes vs the reference sampled at its nodes
    copy_positions(*uni, ux);
    uleaves.resize(net->node_count());
    resample_bilinear({coarse.width(), coarse.height()}, ux, {net->width(), net->height()}, uleaves);
    s_u += pct * surface_error(uleaves, rx).rms;
    sampled.resize(coarse.node_count());
    resample_bilinear({net->width(), net->height()}, rx, {coarse.width(), coarse.height()}, sampled);
    resample_bilinear({coarse.width(), coarse.height()}, sampled, {net->width(), net->height()}, uleaves);
    s_ufloor += pct * surface_error(uleaves, rx).rms;
    s_unode += pct * surface_error(ux, sampled).rms;
    ++n;
  }
  std::printf("net %s level %d (N=%d) k=%.3f: floor(recon of perfect nodes) %.3f  sim recon %.3f  sim "
              "nodes-vs-sampled-at-rest %.3f\n",
              net->spec().name.c_str(), level, body.node_count(), k, s_floor / n, s_tc / n, s_tcnode / n);
  std::printf("  sim recon over the left half %.3f, the right half %.3f\n", s_left / n, s_right / n);
  std::printf("uniform %dx%d k=%.3f: floor(bilinear) %.3f  sim recon %.3f  sim nodes-vs-sampled %.3f\n", coarse.width(),
              coarse.height(), ku, s_ufloor / n, s_u / n, s_unode / n);
}
