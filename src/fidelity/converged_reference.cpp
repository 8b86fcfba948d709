#include "fidelity/converged_reference.h"

#include "analysis/fidelity_metrics.h"
#include "analysis/statistics.h"
#include "fidelity/fidelity_floors.h"
#include "fidelity/reconstruction.h"
#include "scene/scene_world.h"
#include "softbody/bullet_setup.h"
#include "softbody/divergence.h"
#include "softbody/plain_softbody.h"

namespace tcsb {

namespace {

/// A full-resolution body in a world of its own.
struct Runner {
  Runner(const Suite& suite, const Net& net, const SolverSettings& solver)
      : world(suite.world, suite.scene), body(make_plain_softbody(world.info(), net, solver)),
        attachment(world.attach(*body)) {}
  SceneWorld world;
  std::unique_ptr<btSoftBody> body;
  SceneWorld::Attachment attachment;  // after the body: leaves the world first
  std::vector<Eigen::Vector3d> x;
};

/// Seed of the perturbation (any fixed value; the noise floor's own is in fidelity_floors.h).
constexpr std::uint64_t kPerturbationSeed = 0x737562737465ULL;

SubstepDoubling measure_doubling(const Suite& suite, const Net& net, std::size_t net_index, int substeps) {
  SubstepDoubling d;
  d.substeps = substeps;
  Runner coarse(suite, net, with_substeps(suite.solver, substeps));
  Runner perturbed(suite, net, with_substeps(suite.solver, substeps));
  Runner fine(suite, net, with_substeps(suite.solver, 2 * substeps));
  perturb_positions(*perturbed.body, kNoiseFloorPerturbation * net.extent(), kPerturbationSeed + net_index);
  const double to_pct = 100.0 / net.extent();
  std::vector<double> change, noise;
  const int total = suite.warmup_steps + suite.steps;
  for (int s = 0; s < total; ++s) {
    for (Runner* r : {&coarse, &perturbed, &fine}) {
      r->world.step(static_cast<btScalar>(suite.world.dt));
      if (divergence_now(*r->body, net.extent())) {
        d.diverged = true;
        return d;
      }
    }
    if (s < suite.warmup_steps) continue;
    for (Runner* r : {&coarse, &perturbed, &fine}) copy_positions(*r->body, r->x);
    change.push_back(to_pct * surface_error(coarse.x, fine.x).rms);
    noise.push_back(to_pct * surface_error(coarse.x, perturbed.x).rms);
  }
  d.change_rms_pct = mean(change);
  d.noise_rms_pct = mean(noise);
  return d;
}

}  // namespace

ReferenceSubsteps find_reference_substeps(const Suite& suite, const std::shared_ptr<const Net>& net,
                                          std::size_t net_index) {
  ReferenceSubsteps out;
  int substeps = suite.solver.compliant.substeps;
  out.substeps = substeps;
  for (int k = 0; k < kMaxReferenceDoublings; ++k) {
    const SubstepDoubling d = measure_doubling(suite, *net, net_index, substeps);
    out.doublings.push_back(d);
    if (d.diverged) break;  // (keep the last count that stepped)
    if (d.change_rms_pct <= d.noise_rms_pct) {
      out.substeps = substeps;
      out.converged = true;
      return out;
    }
    substeps *= 2;
    out.substeps = substeps;  // not converged yet: at least the finer of the pair
  }
  return out;
}

}  // namespace tcsb
