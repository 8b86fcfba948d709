#include "world/world_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <span>

#include "analysis/statistics.h"
#include "case/body_factory.h"
#include "case/step_clock.h"
#include "feedback/world_budget.h"
#include "fidelity/discrete_lod.h"
#include "fidelity/fidelity_floors.h"
#include "fidelity/grid_state_transfer.h"
#include "fidelity/reconstruction.h"
#include "fidelity/screen_error.h"
#include "fidelity/surface_morph.h"
#include "net/grid_resample.h"
#include "softbody/divergence.h"
#include "softbody/op_sample.h"
#include "softbody/tc_softbody_impl.h"
#include "suite/case_plan.h"
#include "suite/fidelity_plan.h"
#include "suite/scene_bodies.h"
#include "suite/world_plan.h"
#include "view/depth_buffer.h"
#include "world/cut_churn.h"

namespace tcsb {

namespace {

/// Discrete LOD's grids: the net, then each level about a quarter of the one before (every second grid line), as a
/// game's precomputed levels are; four levels span 1/64 of the nodes, below what any budget here asks.
constexpr int kLodLevels = 4;

/// A game's margin against flicker at the thresholds: a body switches coarser beyond 1.1 x its threshold and finer
/// within 0.9 x it (DiscreteLod::hysteresis).
constexpr double kLodHysteresis = 0.1;

/// An operation undone, or a body's nodes turned back, by one of the next two evaluations counts as churn: detail
/// that follows the camera stays for as long as the camera takes to pass a body, many evaluations.
constexpr int kChurnWindowEvaluations = 2;

/// Seeds of the TC-SB bodies' controllers: past every case index, one per body, the same in both TC-SB methods.
constexpr std::size_t kWorldSeedIndex = 200000;

GridSize grid_size_of(const Net& net) { return {net.width(), net.height()}; }

/// One body of a method's scene.
class SceneMember {
 public:
  virtual ~SceneMember() = default;
  /// Work before the world steps (TC-SB's blends, feedback and operations; discrete LOD's switch).
  virtual void boundary(int step) = 0;
  /// Work after the world stepped (TC-SB's controller reads the step).
  virtual void after_step() {}
  /// Whether the last boundary changed the body's resolution, or moved its surface on the way to a change (TC-SB's
  /// geomorph): its surface may have jumped.
  virtual bool resolution_changed() const { return false; }
  /// The surface at the fine net's grid points.
  virtual void reconstruct(std::vector<Eigen::Vector3d>& leaves) = 0;
  /// The LOD level governing each of the fine net's grid points (WorldStepView::levels).
  virtual void leaf_levels(std::vector<int>& levels) const = 0;
  virtual const btSoftBody& bullet() const = 0;
  /// The body and its controller, for a world budget: only TC-SB under a budget.
  virtual std::optional<WorldBudgetMember> budget_member() { return std::nullopt; }
  /// TC-SB's operations over the measured steps (world/cut_churn.h).
  virtual std::optional<ChurnCounts> churn() const { return std::nullopt; }
};

/// A plain body at full resolution.
class FullResolutionMember final : public SceneMember {
 public:
  explicit FullResolutionMember(Body body) : body_(std::move(body)) {}
  void boundary(int) override {}
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override { copy_positions(*body_.bullet, leaves); }
  void leaf_levels(std::vector<int>& levels) const override { levels.assign(body_.net->node_count(), 0); }
  const btSoftBody& bullet() const override { return *body_.bullet; }

 private:
  Body body_;
};

/// TC-SB with its controller, its surface geomorphed as the fidelity pass shows it (fidelity/surface_morph.h).
class TreeCutMember final : public SceneMember {
 public:
  TreeCutMember(const Suite& suite, Body body)
      : suite_(suite), body_(std::move(body)), tc_(*body_.tc), morph_(suite.fidelity.geomorph_boundaries),
        churn_(tc_.tree().size(), kChurnWindowEvaluations * suite.feedback.evaluation_interval, suite.warmup_steps) {
    tc_.impl().set_op_sink(&ops_);
    tc_.set_cut_listener(&churn_);
  }
  ~TreeCutMember() override {
    tc_.set_cut_listener(nullptr);
    tc_.impl().set_op_sink(nullptr);
  }
  void boundary(int step) override {
    if (body_.controller && suite_.feedback.view) tell_spectator(step);
    const std::int64_t before = ops_.count;
    churn_.begin_boundary(step);
    tc_.advance_blends(OrderSettling::kByCaller);
    if (body_.controller) body_.controller->before_step(tc_);
    tc_.settle_order();
    churn_.end_boundary(tc_.committed_count());
    // A geomorphed surface also moves at a boundary without operations while it spreads an earlier jump.
    changed_ = ops_.count != before || morph_.morphing();
    morph_pending_ = changed_;
  }
  void after_step() override {
    if (body_.controller) body_.controller->after_step(tc_);
  }
  bool resolution_changed() const override { return changed_; }
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override {
    if (morph_pending_) morph_.boundary(tc_);
    morph_pending_ = false;
    morph_.reconstruct(tc_, leaves);
  }
  void leaf_levels(std::vector<int>& levels) const override { committed_leaf_levels(tc_, levels); }
  const btSoftBody& bullet() const override { return tc_; }
  std::optional<WorldBudgetMember> budget_member() override {
    if (!body_.controller) return std::nullopt;
    return WorldBudgetMember{&tc_, body_.controller.get()};
  }
  std::optional<ChurnCounts> churn() const override { return churn_.counts(); }

 private:
  /// The camera as a game moves it: each frame the application tells the controller where the spectator stands now
  /// (Controller::set_spectator, the library's call), not a path known in advance. Boundary b sees the state at b x dt,
  /// where the suite's path puts the camera then, so the view terms see what they saw from the path, bit for bit.
  /// With feedback.view_lookahead_s the game also tells where the camera will be then: a path of two keyframes.
  void tell_spectator(int step) {
    Spectator now{*suite_.scene.camera, suite_.world.dt};
    const double t = static_cast<double>(step) * suite_.world.dt;
    now.camera.pose = now.camera.pose_at(t);
    now.camera.path.clear();
    if (const double ahead = suite_.feedback.view_lookahead_s; ahead > 0)
      now.camera.path = {{t, now.camera.pose}, {t + ahead, suite_.scene.camera->pose_at(t + ahead)}};
    body_.controller->set_spectator(now);
  }

  const Suite& suite_;
  Body body_;
  TcSoftBody& tc_;
  SurfaceMorph morph_;
  OpCounter ops_;
  CutChurn churn_;
  bool changed_ = false;
  bool morph_pending_ = false;
};

/// Discrete LOD: a plain body on the grid of its scheduled level, rebuilt on the next level's grid at a switch with
/// its positions and velocities resampled bilinearly (the pinned nodes stay at rest, where the new grid's are).
class DiscreteLodMember final : public SceneMember {
 public:
  /// `levels[s]`: the level at step s; `level_compression[k]`: level k's share of the net's nodes.
  DiscreteLodMember(const Suite& suite, SceneWorld& world, std::shared_ptr<const Net> fine, std::vector<int> levels,
                    std::vector<double> level_compression)
      : suite_(suite), world_(world), fine_(std::move(fine)), levels_(std::move(levels)),
        level_compression_(std::move(level_compression)), level_(levels_.front()),
        body_(make_body(suite_, spec_of(level_), world_, fine_, 0)) {}
  void boundary(int step) override {
    const int wanted = levels_[static_cast<std::size_t>(step)];
    changed_ = wanted != level_;
    if (!changed_) return;
    Body next = make_body(suite_, spec_of(wanted), world_, fine_, 0);
    transfer_grid_state(*body_.bullet, grid_size_of(*body_.net), *next.bullet, *next.net, x_, v_, nx_, nv_);
    body_ = std::move(next);  // frees the old grid's body: part of what a switch costs
    level_ = wanted;
  }
  bool resolution_changed() const override { return changed_; }
  void reconstruct(std::vector<Eigen::Vector3d>& leaves) override {
    copy_positions(*body_.bullet, x_);
    leaves.resize(fine_->node_count());
    resample_bilinear(grid_size_of(*body_.net), x_, grid_size_of(*fine_), leaves);
  }
  void leaf_levels(std::vector<int>& levels) const override { levels.assign(fine_->node_count(), level_); }
  const btSoftBody& bullet() const override { return *body_.bullet; }

 private:
  BodySpec spec_of(int level) const {
    BodySpec spec;
    spec.kind = BodyKind::kUniform;
    spec.compression = level_compression_[static_cast<std::size_t>(level)];
    return spec;
  }

  const Suite& suite_;
  SceneWorld& world_;
  std::shared_ptr<const Net> fine_;
  std::vector<int> levels_;
  std::vector<double> level_compression_;
  int level_;
  Body body_;
  bool changed_ = false;
  std::vector<Eigen::Vector3d> x_, v_, nx_, nv_;
};

/// The reference's surfaces over one block: every body's, one after another, per measured step.
struct WorldReferenceBlock {
  int first_step = 0;
  std::vector<std::vector<Eigen::Vector3d>> surfaces;  // per step of the block (empty for a warm-up step)
  std::vector<std::vector<std::uint8_t>> seen;         // the same, with occlusion: the points the camera sees
};

/// One method's scene: its world, its bodies and its series.
class WorldTrack {
 public:
  WorldTrack(const Suite& suite, std::string method, double budget, std::optional<int> world_budget)
      : suite_(suite), world_(suite.world, suite.scene), world_budget_(world_budget) {
    result.method = std::move(method);
    result.budget = budget;
  }
  SceneWorld& world() { return world_; }
  void add(std::unique_ptr<SceneMember> member, std::shared_ptr<const Net> net) {
    members_.push_back(std::move(member));
    nets_.push_back(std::move(net));
  }
  bool alive() const { return result.status == "ok"; }
  void set_observer(WorldObserver* observer) { observer_ = observer; }

  /// Steps [first, last). With `record` (the reference), writes its surfaces into `reference`; else compares with it.
  void run_block(int first, int last, WorldReferenceBlock& reference, bool record) {
    const std::size_t bodies = members_.size();
    if (surfaces_.empty()) {
      surfaces_.resize(bodies);
      body_nodes_.resize(bodies);
      for (std::size_t b = 0; b < bodies; ++b) members_[b]->reconstruct(surfaces_[b]);
      show_observer(0);
    }
    if (record) {
      reference.first_step = first;
      reference.surfaces.assign(static_cast<std::size_t>(last - first), {});
      reference.seen.assign(static_cast<std::size_t>(last - first), {});
    }
    const std::size_t timed_before = step_ms_.size();
    for (int s = first; s < last && alive(); ++s) {
      const StepClock::time_point t0 = StepClock::now();
      for (auto& m : members_) m->boundary(s);
      const StepClock::time_point t1 = StepClock::now();
      record_popping(s);
      const StepClock::time_point t2 = StepClock::now();
      world_.step(static_cast<btScalar>(suite_.world.dt));
      for (auto& m : members_) m->after_step();
      if (world_budget_) share_budget();
      const StepClock::time_point t3 = StepClock::now();
      for (std::size_t b = 0; b < bodies; ++b)
        if (auto diverged = divergence_now(members_[b]->bullet(), nets_[b]->extent())) {
          stop(s, "body " + std::to_string(b) + ": " + *diverged);
          return;
        }
      for (std::size_t b = 0; b < bodies; ++b) members_[b]->reconstruct(surfaces_[b]);
      show_observer(s + 1);
      if (s < suite_.warmup_steps) continue;
      step_ms_.push_back(ms_between(t0, t1) + ms_between(t2, t3));
      boundary_ms_.push_back(ms_between(t0, t1));
      double nodes = 0;
      for (std::size_t b = 0; b < bodies; ++b) {
        body_nodes_[b].push_back(members_[b]->bullet().m_nodes.size());
        nodes += body_nodes_[b].back();
      }
      nodes_.push_back(nodes);
      gather(surfaces_, all_);
      const std::size_t f = static_cast<std::size_t>(s - first);
      const ScreenProjection view = view_after_steps(*suite_.scene.camera, s + 1, suite_.world.dt);
      if (record) {
        reference.surfaces[f] = all_;
        if (suite_.scene.camera->occlusion_cell_px > 0) see_through_camera(view, reference.seen[f]);
      }
      const ScreenError e = screen_error(view, all_, reference.surfaces[f], reference.seen[f], scratch_);
      if (!std::isfinite(e.p95)) {
        stop(s, "non-finite reconstructed surface");
        return;
      }
      if (e.in_view > 0) p95_.push_back(e.p95);
    }
    add_block_mean(step_ms_, timed_before, result.block_step_ms);
  }

  void pause(bool paused) {
    for (auto& m : members_)
      if (const std::optional<WorldBudgetMember> w = m->budget_member())
        paused ? w->controller->pause() : w->controller->resume();
  }

  void stop(int step, std::string reason) {
    result.status = "diverged";
    result.diverged_step = step;
    result.diverged_reason = std::move(reason);
  }

  /// The summaries; `reference_blocks`: full resolution's block means, for the ratio.
  WorldMethodResult finish(const std::vector<double>& reference_blocks) {
    result.mean_nodes = mean(nodes_);
    for (const std::vector<double>& n : body_nodes_) result.body_mean_nodes.push_back(mean(n));
    result.step_ms = mean(step_ms_);
    result.boundary_ms = mean(boundary_ms_);
    result.p95_px = mean(p95_);
    std::vector<double> ratios;
    for (std::size_t k = 0; k < std::min(reference_blocks.size(), result.block_step_ms.size()); ++k)
      if (reference_blocks[k] > 0) ratios.push_back(result.block_step_ms[k] / reference_blocks[k]);
    for (const auto& m : members_)
      if (const std::optional<ChurnCounts> c = m->churn()) add_churn(*c);
    if (!alive()) result.block_step_ms.clear();  // a part of the blocks would pair with the wrong ones
    result.step_ratio = alive() && !ratios.empty() ? median(ratios) : 0.0;
    return result;
  }

  WorldMethodResult result;

 private:
  /// Before the world moves, nothing but the method's own change can move a surface: its jump is pure popping.
  void record_popping(int step) {
    const ScreenProjection view = view_after_steps(*suite_.scene.camera, step, suite_.world.dt);
    for (std::size_t b = 0; b < members_.size(); ++b) {
      if (!members_[b]->resolution_changed()) continue;
      ++result.resolution_changes;
      members_[b]->reconstruct(after_);
      const ScreenError jump = screen_error(view, after_, surfaces_[b], {}, scratch_);
      result.popping_px = std::max(result.popping_px, jump.max);
      surfaces_[b] = after_;
    }
  }

  void add_churn(const ChurnCounts& body) {
    ChurnCounts& sum = result.churn ? *result.churn : result.churn.emplace();
    sum.refines += body.refines;
    sum.coarsens += body.coarsens;
    sum.undone += body.undone;
    sum.reversals += body.reversals;
    sum.nodes_moved += body.nodes_moved;
  }

  /// Outside the timed intervals, from the surfaces the step reconstructed anyway.
  void show_observer(int steps) {
    if (!observer_ || !observer_->wants(result.method, steps)) return;
    levels_.resize(members_.size());
    int nodes = 0;
    for (std::size_t b = 0; b < members_.size(); ++b) {
      members_[b]->leaf_levels(levels_[b]);
      nodes += members_[b]->bullet().m_nodes.size();
    }
    observer_->observe({result.method, result.budget, steps, surfaces_, levels_, nodes});
  }

  void share_budget() {
    budget_members_.clear();
    for (auto& m : members_)
      if (const std::optional<WorldBudgetMember> w = m->budget_member()) budget_members_.push_back(*w);
    share_world_budget(budget_members_, *world_budget_, suite_.feedback.threshold);
  }

  /// Which reference points the camera sees, every body drawn into one depth buffer (any body may hide another), at
  /// a tolerance of one link's rest length as the fidelity pass's (fidelity_runner.cpp).
  void see_through_camera(const ScreenProjection& view, std::vector<std::uint8_t>& seen) {
    const Camera& camera = *suite_.scene.camera;
    if (!depth_) depth_.emplace(view, camera.occlusion_cell_px);
    const NetSpec& spec = nets_.front()->spec();
    visible_grid_points(view, all_, spec.width, spec.height, spec.link_length(), *depth_, seen);
  }

  static void gather(const std::vector<std::vector<Eigen::Vector3d>>& parts, std::vector<Eigen::Vector3d>& out) {
    out.clear();
    for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  }

  const Suite& suite_;
  SceneWorld world_;
  std::optional<int> world_budget_;
  std::vector<std::unique_ptr<SceneMember>> members_;
  std::vector<std::shared_ptr<const Net>> nets_;
  std::vector<WorldBudgetMember> budget_members_;
  std::vector<std::vector<Eigen::Vector3d>> surfaces_;  // per body, after the last step ("before" a boundary)
  std::vector<Eigen::Vector3d> after_, all_;
  std::vector<double> step_ms_, boundary_ms_, nodes_, p95_, scratch_;
  std::vector<std::vector<double>> body_nodes_;
  std::optional<DepthBuffer> depth_;
  WorldObserver* observer_ = nullptr;
  std::vector<std::vector<int>> levels_;  // per body, for the observer
};

/// Level k's share of the net's nodes: 4^-k, as long as the grid still shrinks.
std::vector<double> lod_level_compressions(const Net& net, std::vector<int>& level_nodes) {
  std::vector<double> compressions{1.0};
  level_nodes = {static_cast<int>(net.node_count())};
  for (int k = 1; k < kLodLevels; ++k) {
    const double c = compressions.back() / 4.0;
    const int nodes = static_cast<int>(coarse_net_spec(net.spec(), node_budget(net, c)).node_count());
    if (nodes >= level_nodes.back()) break;
    compressions.push_back(c);
    level_nodes.push_back(nodes);
  }
  return compressions;
}

/// Every body plain at full resolution with the suite's passes divided by `solver_divisor`; with `perturbed`, each
/// started perturbed as the fidelity pass's noise floor is (fidelity/fidelity_floors.h).
std::unique_ptr<WorldTrack> full_resolution_track(const Suite& suite, const char* method, int solver_divisor,
                                                  bool perturbed, const std::vector<std::shared_ptr<const Net>>& nets) {
  auto track = std::make_unique<WorldTrack>(suite, method, 1.0, std::nullopt);
  track->result.solver_divisor = solver_divisor;
  for (std::size_t b = 0; b < nets.size(); ++b) {
    BodySpec spec;
    spec.kind = BodyKind::kPlain;
    spec.solver_divisor = solver_divisor;
    Body body = make_body(suite, spec, track->world(), nets[b], 0);
    if (perturbed) perturb_positions(*body.bullet, kNoiseFloorPerturbation * nets[b]->extent(), kNoiseFloorSeed + b);
    track->add(std::make_unique<FullResolutionMember>(std::move(body)), nets[b]);
  }
  return track;
}

}  // namespace

WorldResult run_world(const Suite& suite, WorldObserver* observer) {
  const StepClock::time_point start = StepClock::now();
  const std::vector<NetSpec> placed = scene_body_nets(suite);
  std::vector<std::shared_ptr<const Net>> nets;
  for (const NetSpec& spec : placed) nets.push_back(std::make_shared<const Net>(spec, spec.lod_rest));
  WorldResult result;
  result.bodies = static_cast<int>(nets.size());
  for (const auto& n : nets) result.scene_nodes += n->node_count();
  const int total = suite.warmup_steps + suite.steps;

  std::vector<std::unique_ptr<WorldTrack>> tracks;
  tracks.push_back(full_resolution_track(suite, "full_resolution", 1, false, nets));
  std::vector<int> level_nodes;
  const std::vector<double> level_compressions = lod_level_compressions(*nets.front(), level_nodes);
  const std::vector<double> distances = lod_camera_distances(suite, total);
  const std::size_t first_measured = static_cast<std::size_t>(suite.warmup_steps) * nets.size();
  for (const double c : world_budgets(suite)) {
    const int world_budget = static_cast<int>(std::llround(c * static_cast<double>(result.scene_nodes)));
    const auto add_tcsb = [&](const char* method, std::optional<int> shared) {
      auto track = std::make_unique<WorldTrack>(suite, method, c, shared);
      for (std::size_t b = 0; b < nets.size(); ++b) {
        BodySpec spec;
        spec.compression = c;
        Body body = make_body(suite, spec, track->world(), nets[b], case_seed(suite, kWorldSeedIndex + b));
        track->add(std::make_unique<TreeCutMember>(suite, std::move(body)), nets[b]);
      }
      tracks.push_back(std::move(track));
    };
    if (suite.feedback.budget_scope == BudgetScope::kWorld) add_tcsb("tcsb_world", world_budget);
    add_tcsb("tcsb_body", std::nullopt);
    // Fitted and scheduled over the measured steps, whose mean node count is the one reported; the warm-up holds
    // the first measured step's levels.
    const std::span<const double> measured(distances.begin() + static_cast<std::ptrdiff_t>(first_measured),
                                           distances.end());
    const DiscreteLod lod = fit_discrete_lod(level_nodes, measured, nets.size(), world_budget, kLodHysteresis);
    const std::vector<int> schedule = lod_schedule(lod, measured, nets.size());
    auto track = std::make_unique<WorldTrack>(suite, "discrete_lod", c, std::nullopt);
    track->result.lod_scale = lod.scale;
    for (std::size_t b = 0; b < nets.size(); ++b) {
      std::vector<int> levels(static_cast<std::size_t>(total));
      for (int s = 0; s < total; ++s)
        levels[static_cast<std::size_t>(s)] =
            schedule[static_cast<std::size_t>(std::max(0, s - suite.warmup_steps)) * nets.size() + b];
      track->add(std::make_unique<DiscreteLodMember>(suite, track->world(), nets[b], std::move(levels),
                                                     level_compressions),
                 nets[b]);
    }
    tracks.push_back(std::move(track));
  }
  // The rivals' finest points and full resolution's curve of fewer passes (paper/world_equal_error.h).
  if (const std::optional<FidelityCurves>& curves = suite.fidelity.curves) {
    tracks.push_back(full_resolution_track(suite, "noise_floor", 1, true, nets));
    for (const int d : curves->solver_divisors)
      tracks.push_back(full_resolution_track(suite, "full_resolution", d, false, nets));
  }

  for (auto& t : tracks) t->set_observer(observer);
  // Full resolution first in each block: the others are measured against the frames it records.
  WorldReferenceBlock frames;
  WorldTrack& full = *tracks.front();
  for (int first = 0; first < total; first += kWorldBlockSteps) {
    const int last = std::min(total, first + kWorldBlockSteps);
    full.run_block(first, last, frames, true);
    if (!full.alive()) {
      for (std::size_t t = 1; t < tracks.size(); ++t)
        if (tracks[t]->alive()) tracks[t]->stop(*full.result.diverged_step, "the reference diverged");
      break;
    }
    for (std::size_t t = 1; t < tracks.size(); ++t) {
      if (!tracks[t]->alive()) continue;
      tracks[t]->pause(false);
      tracks[t]->run_block(first, last, frames, false);
      tracks[t]->pause(true);
    }
  }
  const std::vector<double> reference_blocks = tracks.front()->result.block_step_ms;
  for (auto& t : tracks) result.methods.push_back(t->finish(reference_blocks));
  result.wall_s = std::chrono::duration<double>(StepClock::now() - start).count();
  return result;
}

}  // namespace tcsb
