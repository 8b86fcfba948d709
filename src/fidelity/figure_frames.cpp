#include "fidelity/figure_frames.h"

#include <memory>
#include <stdexcept>

#include "case/case_body.h"
#include "fidelity/fidelity_subject.h"
#include "fidelity/reconstruction.h"
#include "softbody/divergence.h"
#include "softbody/tc_softbody_impl.h"
#include "suite/fidelity_plan.h"

namespace tcsb {

namespace {

FigureFrame capture(int step, const CaseBody& plain, const TcSoftBody& tc, const std::vector<Eigen::Vector3d>& surface,
                    const FidelitySubject* uniform) {
  FigureFrame f;
  f.step = step;
  copy_positions(plain.bullet(), f.plain);
  f.tcsb_surface = surface;
  copy_positions(tc, f.tcsb_nodes);
  for (const TreeId id : tc.tree_ids()) f.tcsb_levels.push_back(tc.tree().node(id).level);
  if (uniform) copy_positions(uniform->bullet(), f.uniform_nodes);
  const btSoftBody::Node* first = &tc.m_nodes[0];
  f.tcsb_links.reserve(static_cast<std::size_t>(tc.m_links.size()));
  for (int i = 0; i < tc.m_links.size(); ++i) {
    const btSoftBody::Link& l = tc.m_links[i];
    f.tcsb_links.push_back(
        {static_cast<int>(l.m_n[0] - first), static_cast<int>(l.m_n[1] - first), tc.impl().link_role(i)});
  }
  f.interpolations = tc.interpolations();
  return f;
}

}  // namespace

FigureFrames record_figure_frames(const Suite& suite, std::size_t net_index, double compression,
                                  const std::vector<int>& steps, bool calibrated) {
  if (net_index >= suite.nets.size()) throw std::invalid_argument("record_figure_frames: no such net");
  if (!(compression > 0 && compression <= 1)) throw std::invalid_argument("record_figure_frames: compression");
  if (calibrated && !suite.calibration)
    throw std::invalid_argument("record_figure_frames: the suite has no calibration");
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i] < 0 || (i > 0 && steps[i] <= steps[i - 1]))
      throw std::invalid_argument("record_figure_frames: steps must be ascending, distinct and >= 0");
  }
  const NetSpec& spec = suite.nets[net_index];
  const auto net = std::make_shared<const Net>(spec);
  FigureFrames out;
  out.net = spec.name;
  out.width = spec.width;
  out.height = spec.height;
  out.extent = net->extent();
  out.compression = compression;
  out.calibrated = calibrated;

  // Plain Bullet built as the timed cases' bodies are; TC-SB as the fidelity pass builds it, so its surface is the
  // one the pass measures (geomorphed, SurfaceMorph), boundary by boundary. The saliency controller draws no random
  // numbers (a random policy would draw from the suite's seed).
  const CaseKey plain_key{net_index, Method::kPlain, std::nullopt};
  // One world per body: a body keeps its world's address, and each steps its own.
  SceneWorld plain_world(suite.world, suite.scene), tc_world(suite.world, suite.scene);
  const std::unique_ptr<CaseBody> plain = make_case_body(suite, plain_key, plain_world, net, suite.seed);
  const FidelitySubjectSpec subject = fidelity_subject(calibrated ? "tcsb_calibrated" : "tcsb", compression);
  const std::unique_ptr<FidelitySubject> tc =
      make_fidelity_subject(suite, subject.body, tc_world, net, suite.seed, nullptr, 0);
  const auto& tc_body = dynamic_cast<const TcSoftBody&>(tc->bullet());
  // What the camera compares TC-SB with: the static grid of its node count.
  SceneWorld uniform_world(suite.world, suite.scene);
  std::unique_ptr<FidelitySubject> uniform;
  if (suite.scene.camera) {
    const FidelitySubjectSpec grid =
        fidelity_subject(calibrated ? "uniform_grid_calibrated" : "uniform_grid", compression);
    uniform = make_fidelity_subject(suite, grid.body, uniform_world, net, suite.seed, nullptr, 0);
    const CoarseGrid g = coarse_grid_for(spec.width, spec.height, node_budget(*net, compression));
    out.uniform_width = g.width;
    out.uniform_height = g.height;
  }

  if (steps.empty()) return out;
  const btScalar dt = static_cast<btScalar>(suite.world.dt);
  std::vector<Eigen::Vector3d> surface;
  tc->reconstruct(surface);
  std::size_t next = 0;
  for (int s = 0;; ++s) {
    if (steps[next] == s) {
      out.frames.push_back(capture(s, *plain, tc_body, surface, uniform.get()));
      if (++next == steps.size()) break;
    }
    plain->step(dt);
    tc->boundary(s);
    if (tc->surface_changed()) tc->reconstruct(surface);  // the morph records the boundary's jump before the step
    tc->simulate(dt);
    tc->reconstruct(surface);
    if (uniform) {
      uniform->boundary(s);
      uniform->simulate(dt);
    }
    for (const btSoftBody* body : {&plain->bullet(), &tc->bullet()}) {
      if (auto diverged = divergence_now(*body, net->extent())) {  // untimed: check fully every step
        out.diverged_step = s;
        out.diverged_reason = std::string(body == &plain->bullet() ? "plain: " : "tcsb: ") + *diverged;
        return out;
      }
    }
  }
  return out;
}

const char* link_role_name(LinkRole role) {
  switch (role) {
    case LinkRole::kSteady: return "steady";
    case LinkRole::kFadeIn: return "fade_in";
    case LinkRole::kFadeOut: return "fade_out";
    case LinkRole::kDoomed: return "doomed";
    case LinkRole::kTether: return "tether";
  }
  return "unknown";
}

}  // namespace tcsb
