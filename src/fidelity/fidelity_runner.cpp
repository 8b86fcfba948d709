#include "fidelity/fidelity_runner.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>

#include "analysis/fidelity_metrics.h"
#include "analysis/statistics.h"
#include "case/body_factory.h"
#include "case/state_hash.h"
#include "case/step_clock.h"
#include "feedback/cut_snapshot.h"
#include "feedback/saliency.h"
#include "fidelity/converged_reference.h"
#include "fidelity/fidelity_floors.h"
#include "fidelity/fidelity_subject.h"
#include "fidelity/reconstruction.h"
#include "fidelity/screen_error.h"
#include "softbody/bullet_setup.h"
#include "softbody/divergence.h"
#include "softbody/plain_softbody.h"
#include "suite/case_plan.h"
#include "view/depth_buffer.h"

namespace tcsb {

namespace {

/// Bodies are stepped in blocks of this many steps, round-robin: the reference's block first (recorded), then each
/// subject's same block. Long enough that a body's first, cache-cold step after the others ran is 1 step in 20;
/// short enough that machine drift over a pass (other processes, frequency) hits every body alike — the time ratios
/// are interleaved, like the repetitions of the timed cases.
constexpr int kBlockSteps = 20;

/// The scene's camera as it saw the end of step `step` (at (step + 1) x dt), when the scene has one.
std::optional<ScreenProjection> camera_view(const Suite& suite, int step) {
  if (!suite.scene.camera) return std::nullopt;
  return view_after_steps(*suite.scene.camera, step + 1, suite.world.dt);
}

/// The reference's trajectory over one block of steps. Positions are Bullet's floats, kept as floats.
struct ReferenceBlock {
  int first_step = 0;  // step of frame 0
  std::size_t nodes = 0;
  std::vector<std::array<float, 3>> positions;  // frame f: [f * nodes, (f + 1) * nodes)
  std::vector<float> saliency;                  // same layout
  std::vector<std::uint8_t> seen;               // same layout, when the camera models occlusion: the points it sees
  std::vector<double> energy;                   // per frame

  void frame(int step, std::vector<Eigen::Vector3d>& x) const {
    const std::size_t f = static_cast<std::size_t>(step - first_step);
    x.resize(nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
      const std::array<float, 3>& p = positions[f * nodes + i];
      x[i] = Eigen::Vector3d(p[0], p[1], p[2]);
    }
  }
  std::span<const float> weights(int step) const {
    return {saliency.data() + static_cast<std::size_t>(step - first_step) * nodes, nodes};
  }
  /// Which points the spectator sees at `step`; empty (every point in view counts) without occlusion.
  std::span<const std::uint8_t> seen_at(int step) const {
    if (seen.empty()) return {};
    return {seen.data() + static_cast<std::size_t>(step - first_step) * nodes, nodes};
  }
};

/// The reference: the plain body at full resolution, its timed steps and its recorded frames.
class Reference {
 public:
  /// `solver`: the suite's, or under the compliant material the converged reference's small steps.
  Reference(const Suite& suite, const std::shared_ptr<const Net>& net, const SolverSettings& solver)
      : suite_(suite), net_(net), world_(suite.world, suite.scene),
        body_(make_plain_softbody(world_.info(), *net, solver)), attachment_(world_.attach(*body_)), finest_(*net) {
    copy_positions(*body_, x_);
    copy_velocities(*body_, v_);
    initial_energy = mechanical_energy(net->masses(), x_, v_, suite.world.gravity);
    block.nodes = net->node_count();
  }

  /// Steps [first, last) and records the measured ones; false once diverged.
  bool run_block(int first, int last) {
    const int warmup = suite_.warmup_steps;
    const std::size_t frames = static_cast<std::size_t>(last - first), n = block.nodes;
    block.first_step = first;
    block.positions.resize(frames * n);
    block.saliency.resize(frames * n);
    block.energy.assign(frames, 0.0);
    const bool occlusion = suite_.scene.camera && suite_.scene.camera->occlusion_cell_px > 0;
    block.seen.resize(occlusion ? frames * n : 0);
    const std::size_t timed_before = step_ms.size();
    for (int s = first; s < last; ++s) {
      const StepClock::time_point t0 = StepClock::now();
      world_.step(static_cast<btScalar>(suite_.world.dt));
      const StepClock::time_point t1 = StepClock::now();
      // Every step, fully: this loop copies every node after each step anyway, so the check adds no new cache
      // traffic to the steps it times, and the pass reports the first diverged step.
      if (auto diverged = divergence_now(*body_, net_->extent())) {
        diverged_step = s;
        diverged_reason = "the reference diverged: " + *diverged;
        return false;
      }
      if (s < warmup) continue;
      step_ms.push_back(ms_between(t0, t1));
      const std::size_t f = static_cast<std::size_t>(s - first);
      copy_positions(*body_, x_);
      copy_velocities(*body_, v_);
      for (std::size_t i = 0; i < n; ++i)  // back to float: exact, Bullet's positions are floats
        block.positions[f * n + i] = {static_cast<float>(x_[i].x()), static_cast<float>(x_[i].y()),
                                      static_cast<float>(x_[i].z())};
      block.energy[f] = mechanical_energy(net_->masses(), x_, v_, suite_.world.gravity);
      const bool contact = suite_.feedback.contact_saliency > 0;
      if (contact) nodes_in_contact(*body_, finest_.view().tree_of, contacts_);
      // The weights of the weighted error are the saliency the suite's TC-SB uses: seen by its spectator, if any.
      const std::optional<ScreenProjection> view = suite_.feedback.view ? camera_view(suite_, s) : std::nullopt;
      take_snapshot(*body_, finest_.view(), suite_.feedback.illumination || view, s, snapshot_,
                    contact ? &contacts_ : nullptr);
      if (occlusion) see_through_camera(s, f);
      // With occlusion the weights see it as the suite's TC-SB does: a point the grid's own surface hides weighs 0.
      const std::span<const std::uint8_t> seen = view && occlusion ? seen_ : std::span<const std::uint8_t>{};
      const std::vector<float> saliency = compute_saliency(snapshot_, suite_.feedback, view ? &*view : nullptr, seen);
      std::copy(saliency.begin(), saliency.end(), block.saliency.begin() + static_cast<std::ptrdiff_t>(f * n));
    }
    add_block_mean(step_ms, timed_before, block_step_ms);
    return true;
  }

  ReferenceBlock block;
  double initial_energy = 0;  // at rest, before the first step: the drift's denominator
  std::vector<double> step_ms;
  std::vector<double> block_step_ms;  // per block with measured steps: their mean
  std::optional<int> diverged_step;
  std::string diverged_reason;

 private:
  /// Records which points the camera sees at the end of step `step` (frame f of the block): those its depth buffer
  /// of the reference's surface does not hide, at a tolerance of one link's rest length (view/depth_buffer.h: a
  /// surface seen edge-on must not hide itself; folds closer than a link count as one layer).
  void see_through_camera(int step, std::size_t f) {
    const Camera& camera = *suite_.scene.camera;
    const ScreenProjection view = *camera_view(suite_, step);
    if (!depth_) depth_.emplace(view, camera.occlusion_cell_px);
    const NetSpec& spec = net_->spec();
    visible_grid_points(view, x_, net_->width(), net_->height(), spec.link_length(), *depth_, seen_);
    std::copy(seen_.begin(), seen_.end(), block.seen.begin() + static_cast<std::ptrdiff_t>(f * block.nodes));
  }

  const Suite& suite_;
  std::shared_ptr<const Net> net_;
  SceneWorld world_;
  std::unique_ptr<btSoftBody> body_;
  SceneWorld::Attachment attachment_;  // after the body: leaves the world first
  FinestCut finest_;
  CutSnapshot snapshot_;
  std::vector<TreeId> contacts_;
  std::vector<Eigen::Vector3d> x_, v_;
  std::optional<DepthBuffer> depth_;  // the camera's image is one size throughout: one buffer, cleared each step
  std::vector<std::uint8_t> seen_;
};

/// One subject on one net: its body and the per-step series of its metrics.
class Track {
 public:
  /// `pace`: for switch_body, the TC-SB subject at the same target (its track must run each block first).
  Track(const Suite& suite, std::size_t net_index, const std::shared_ptr<const Net>& net,
        const FidelitySubjectSpec& spec, const FidelitySubject* pace)
      : suite_(suite), net_(net), world_(suite.world, suite.scene) {
    result.net = net_index;
    result.net_name = net->spec().name;
    result.subject = spec;
    result.target_nodes = node_budget(*net, spec.body.compression);
    // Without a pace (not in fidelity_plan()'s subjects) the switch happens at the first measured boundary.
    body_ = make_fidelity_subject(suite, spec.body, world_, net, fidelity_seed(suite, net_index, spec), pace,
                                  suite.warmup_steps);
    result.grid = body_->grid();
    body_->reconstruct(surface_);
  }

  bool alive() const { return result.status == "ok"; }
  const FidelitySubject& subject() const { return *body_; }

  /// Steps [first, last), comparing every measured step with the reference's frame.
  void run_block(int first, int last, const ReferenceBlock& reference, double reference_energy0) {
    const int warmup = suite_.warmup_steps;
    const double to_pct = 100.0 / net_->extent();
    body_->resume();  // its feedback worker spins again before the first timed step, not woken late inside it
    const std::size_t timed_before = step_ms_.size();
    for (int s = first; s < last && alive(); ++s) {
      const bool measured = s >= warmup;
      const StepClock::time_point t0 = StepClock::now();
      body_->boundary(s);
      const StepClock::time_point t1 = StepClock::now();
      // No simulated time passes between the previous step's end and this point, so the reference does not move:
      // any jump of the surface is pure popping. Measured at every boundary, warm-up included: "every operation"
      // includes TC-SB's first coarsening and a switch made before the measured steps.
      double pop = 0;
      if (body_->surface_changed()) {
        body_->reconstruct(after_);
        pop = max_displacement(surface_, after_);
      }
      const StepClock::time_point t2 = StepClock::now();
      body_->simulate(static_cast<btScalar>(suite_.world.dt));
      const StepClock::time_point t3 = StepClock::now();
      if (auto diverged = divergence_now(body_->bullet(), net_->extent())) {  // every step: see run_block
        stop(s, *diverged);
        break;
      }
      popping_.push_back(to_pct * pop);
      if (!std::isfinite(pop)) {  // a NaN Bullet's bounds missed
        stop(s, "non-finite reconstructed surface");
        break;
      }
      body_->reconstruct(surface_);  // the next boundary's "before"
      if (!measured) continue;
      reference.frame(s, reference_x_);
      const SurfaceError e = surface_error(surface_, reference_x_, reference.weights(s));
      if (!std::isfinite(e.rms) || !std::isfinite(e.max)) {
        stop(s, "non-finite reconstructed surface");
        break;
      }
      step_ms_.push_back(ms_between(t0, t1) + ms_between(t2, t3));
      nodes_.push_back(body_->bullet().m_nodes.size());
      rms_.push_back(to_pct * e.rms);
      max_.push_back(to_pct * e.max);
      weighted_.push_back(to_pct * e.weighted_rms);
      if (const std::optional<ScreenProjection> view = camera_view(suite_, s))
        screen_.add(screen_error(*view, surface_, reference_x_, reference.seen_at(s), scratch_));
      const double drift = energy_drift_pct(body_->energy(suite_.world.gravity),
                                            reference.energy[static_cast<std::size_t>(s - first)], reference_energy0);
      if (std::isfinite(drift)) drift_.push_back(drift);  // undefined only for an initial energy of 0 (net at y = 0)
    }
    if (alive()) add_block_mean(step_ms_, timed_before, result.block_step_ms);
    body_->pause();  // the other subjects run their blocks now: no feedback worker should spin meanwhile
  }

  void stop(int step, std::string reason) {
    result.status = "diverged";
    result.diverged_step = step;
    result.diverged_reason = std::move(reason);
  }

  /// Summaries of the series; `reference_ms` is the reference's mean step.
  FidelityCase finish(double reference_ms) {
    result.rms_pct = summarize_metric(rms_);
    result.max_pct = summarize_metric(max_);
    result.weighted_rms_pct = summarize_metric(weighted_);
    result.popping_pct = summarize_metric(popping_);
    result.energy_drift_pct = summarize_metric(drift_);
    if (suite_.scene.camera) result.screen = screen_.finish();
    result.step_ms = mean(step_ms_);
    result.reference_step_ms = reference_ms;
    if (!alive()) result.block_step_ms.clear();  // a part of the blocks would pair with the wrong ones
    result.mean_nodes = mean(nodes_);
    result.switch_ms = body_->switch_ms();
    result.switch_step = body_->switch_step();
    result.converged_step = body_->converged_step();
    result.final_state_hash = state_hash(body_->bullet());
    return result;
  }

  FidelityCase result;

 private:
  const Suite& suite_;
  std::shared_ptr<const Net> net_;
  SceneWorld world_;  // one per subject: a body keeps its world's address
  std::unique_ptr<FidelitySubject> body_;
  std::vector<Eigen::Vector3d> surface_, after_, reference_x_;  // surface_: after the last step ("before" a boundary)
  std::vector<double> rms_, max_, weighted_, popping_, drift_, step_ms_, nodes_;
  ScreenErrorSeries screen_;
  std::vector<double> scratch_;
};

/// The floors of one net (fidelity/fidelity_floors.h): a perturbed copy of the reference stepped in lockstep with it,
/// and the reference's recorded frames resampled through each budget's uniform rest grid, both compared with the
/// reference's frames of the measured steps by the subjects' metric.
class FloorTrack {
 public:
  /// `solver`: the reference's.
  FloorTrack(const Suite& suite, std::size_t net_index, const std::shared_ptr<const Net>& net,
             const std::vector<FidelitySubjectSpec>& plan, const SolverSettings& solver)
      : suite_(suite), net_(net), world_(suite.world, suite.scene),
        body_(make_plain_softbody(world_.info(), *net, solver)), attachment_(world_.attach(*body_)) {
    perturb_positions(*body_, kNoiseFloorPerturbation * net->extent(), kNoiseFloorSeed + net_index);
    result.net = net_index;
    result.net_name = net->spec().name;
    std::vector<double> budgets;
    for (const FidelitySubjectSpec& spec : plan)
      if (std::none_of(budgets.begin(), budgets.end(), [&](double b) { return b == spec.body.compression; }))
        budgets.push_back(spec.body.compression);
    std::sort(budgets.begin(), budgets.end());
    for (const double b : budgets) {
      const CoarseGrid g = coarse_grid_for(net->width(), net->height(), node_budget(*net, b));
      grids_.push_back({g.width, g.height});
      result.interpolation.push_back({b, std::to_string(g.width) + "x" + std::to_string(g.height), {}});
    }
    interpolation_.resize(budgets.size());
  }

  /// Steps the perturbed body over [first, last) and measures both floors at every measured step.
  void run_block(int first, int last, const ReferenceBlock& reference) {
    const double to_pct = 100.0 / net_->extent();
    const GridSize fine{net_->width(), net_->height()};
    for (int s = first; s < last; ++s) {
      if (perturbed_alive_) {
        world_.step(static_cast<btScalar>(suite_.world.dt));
        if (divergence_now(*body_, net_->extent())) {
          perturbed_alive_ = false;  // no floor rather than one over part of the steps
          noise_.clear();
          noise_screen_ = {};
        }
      }
      if (s < suite_.warmup_steps) continue;
      reference.frame(s, reference_x_);
      if (perturbed_alive_) {
        copy_positions(*body_, x_);
        noise_.push_back(to_pct * surface_error(x_, reference_x_).rms);
        if (const std::optional<ScreenProjection> view = camera_view(suite_, s))
          noise_screen_.add(screen_error(*view, x_, reference_x_, reference.seen_at(s), scratch_));
      }
      for (std::size_t k = 0; k < grids_.size(); ++k) {
        resample_through(fine, reference_x_, grids_[k], coarse_, x_);
        interpolation_[k].push_back(to_pct * surface_error(x_, reference_x_).rms);
      }
    }
  }

  FidelityFloors finish() {
    result.noise_rms_pct = summarize_metric(noise_);
    if (suite_.scene.camera && perturbed_alive_) result.noise_screen = noise_screen_.finish();
    for (std::size_t k = 0; k < grids_.size(); ++k)
      result.interpolation[k].rms_pct = summarize_metric(interpolation_[k]);
    return result;
  }

  FidelityFloors result;

 private:
  const Suite& suite_;
  std::shared_ptr<const Net> net_;
  SceneWorld world_;
  std::unique_ptr<btSoftBody> body_;
  SceneWorld::Attachment attachment_;  // after the body: leaves the world first
  bool perturbed_alive_ = true;
  std::vector<GridSize> grids_;
  std::vector<Eigen::Vector3d> reference_x_, x_, coarse_;
  std::vector<double> noise_;
  ScreenErrorSeries noise_screen_;
  std::vector<double> scratch_;
  std::vector<std::vector<double>> interpolation_;
};

/// The pass on one net: the reference and every subject, interleaved in blocks.
void run_net(const Suite& suite, std::size_t net_index, const std::shared_ptr<const Net>& net,
             const std::vector<FidelitySubjectSpec>& plan, FidelityResult& out) {
  // Bullet's model: the suite's own full-resolution body. The compliant material: the same material in small steps
  // doubled until they no longer change the cloth (converged_reference.h).
  std::optional<ReferenceSubsteps> substeps;
  if (suite.solver.compliant_model()) substeps = find_reference_substeps(suite, net, net_index);
  const SolverSettings solver = substeps ? with_substeps(suite.solver, substeps->substeps) : suite.solver;
  Reference reference(suite, net, solver);
  FloorTrack floors(suite, net_index, net, plan, solver);
  floors.result.reference = substeps;
  std::vector<std::unique_ptr<Track>> tracks;
  for (const FidelitySubjectSpec& spec : plan) {
    // fidelity_plan() lists TC-SB at every suite target before the ablations, so a switch finds its pace here and
    // the pace's track steps each block before it.
    const FidelitySubject* pace = nullptr;
    for (const auto& t : tracks)
      if (spec.method == "switch_body" && t->result.subject.method == "tcsb" &&
          t->result.subject.body.compression == spec.body.compression)
        pace = &t->subject();
    tracks.push_back(std::make_unique<Track>(suite, net_index, net, spec, pace));
  }
  const int total = suite.warmup_steps + suite.steps;
  for (int first = 0; first < total; first += kBlockSteps) {
    const int last = std::min(total, first + kBlockSteps);
    if (!reference.run_block(first, last)) {
      for (auto& t : tracks)
        if (t->alive()) t->stop(*reference.diverged_step, reference.diverged_reason);
      break;
    }
    floors.run_block(first, last, reference.block);
    for (auto& t : tracks)
      if (t->alive()) t->run_block(first, last, reference.block, reference.initial_energy);
  }
  const double reference_ms = mean(reference.step_ms);
  for (auto& t : tracks) out.cases.push_back(t->finish(reference_ms));
  out.floors.push_back(floors.finish());
  out.floors.back().reference_block_step_ms = reference.block_step_ms;
}

}  // namespace

std::uint64_t fidelity_seed(const Suite& suite, std::size_t net, const FidelitySubjectSpec& spec) {
  const std::vector<CaseKey> keys = expand_cases(suite);
  if (spec.method == "tcsb") {
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i].net == net && keys[i].method == Method::kTcsb && keys[i].compression == spec.body.compression)
        return case_seed(suite, i);
  }
  // Past every case index; distinct per net, method and target.
  const auto target = static_cast<std::uint64_t>(std::llround(spec.body.compression * 1000.0));
  const auto variant = static_cast<std::uint64_t>(fidelity_variant_index(spec.method));
  return case_seed(suite, 100000) + net * 10000ULL + variant * 1001ULL + target;
}

FidelityResult run_fidelity(const Suite& suite, const std::vector<std::shared_ptr<const Net>>& nets,
                            const FidelityProgress& progress) {
  const StepClock::time_point start = StepClock::now();
  FidelityResult result;
  result.rms_threshold_pct = suite.fidelity.rms_threshold_pct;
  const std::vector<FidelitySubjectSpec> plan = fidelity_plan(suite);
  if (!plan.empty()) {
    for (std::size_t n = 0; n < nets.size(); ++n) {
      if (!nets[n]) continue;  // another shard's net
      run_net(suite, n, nets[n], plan, result);
      if (progress) progress(nets[n]->spec().name);
    }
  }
  result.wall_s = std::chrono::duration<double>(StepClock::now() - start).count();
  return result;
}

}  // namespace tcsb
