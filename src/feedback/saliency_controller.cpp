#include "feedback/saliency_controller.h"

#include <algorithm>
#include <stdexcept>

#include "feedback/interface_balance.h"
#include "feedback/pin_tension.h"
#include "feedback/saliency.h"

namespace tcsb {

namespace {
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }
}  // namespace

SaliencyController::SaliencyController(const FeedbackSettings& settings, int node_budget,
                                       std::optional<Spectator> spectator)
    : settings_(settings), spectator_(std::move(spectator)), node_budget_(node_budget), time_budget_(node_budget) {
  if (settings_.parallel) workers_ = std::make_unique<FeedbackWorkers>(std::max(1, settings_.threads));
}

SaliencyController::~SaliencyController() {
  if (!workers_) return;
  // The worker may still read the body's cut: join it. What it threw is an error only for a caller of after_step(),
  // which rethrows it; here the body is going away (perhaps during that very exception's unwinding), so it is dropped.
  try {
    workers_->wait();
  } catch (...) {
  }
}

int SaliencyController::budget() const { return std::min(node_budget_, time_budget_); }

void SaliencyController::evaluate() {
  const Clock::time_point t0 = Clock::now();
  const std::size_t n = snapshot_.size();
  saliency_.resize(n);
  neighbour_sums(snapshot_, sums_);
  // The camera where it stood at the snapshot's boundary.
  std::optional<ScreenProjection> view;
  if (spectator_) view.emplace(spectator_->camera, static_cast<double>(snapshot_.step) * spectator_->dt);
  const ScreenProjection* seen = view ? &*view : nullptr;
  const std::span<const std::uint8_t> visible = view && occlusion_cell_px() > 0
                                                    ? occlusion_.seen(snapshot_, *view, occlusion_cell_px())
                                                    : std::span<const std::uint8_t>{};
  // The local motion as `through` sees it, into `out`: in chunks on the workers when there are several (chunks write
  // disjoint ranges; the normalisation and ranking run after the join: same numbers for any split).
  const int threads = workers_ ? workers_->threads() : 1;
  const auto motion_through = [&](const ScreenProjection* through, std::vector<float>& out) {
    if (threads <= 1) return local_motion(snapshot_, sums_, 0, n, out, through);
    const int chunks = threads * 4;
    workers_->parallel_for(chunks, [&](int c) {
      const std::size_t begin = n * static_cast<std::size_t>(c) / static_cast<std::size_t>(chunks);
      const std::size_t end = n * static_cast<std::size_t>(c + 1) / static_cast<std::size_t>(chunks);
      local_motion(snapshot_, sums_, begin, end, out, through);
    });
  };
  motion_through(seen, saliency_);
  finish_saliency(snapshot_, settings_, saliency_, seen, visible);
  if (view && settings_.view_lookahead_s > 0) {
    // The cloth as the spectator will see it: a node is worth the larger of now and then.
    const ScreenProjection then(spectator_->camera,
                                static_cast<double>(snapshot_.step) * spectator_->dt + settings_.view_lookahead_s);
    ahead_.resize(n);
    motion_through(&then, ahead_);
    finish_saliency(snapshot_, settings_, ahead_, &then, {});
    for (std::size_t i = 0; i < n; ++i) saliency_[i] = std::max(saliency_[i], ahead_[i]);
  }
  JumpCharge charge;
  const bool charge_px = view && settings_.view_popping_charge > 0;
  if (settings_.popping_charge > 0 || charge_px) {
    cut_neighbours(snapshot_.cut, neighbours_);
    charge = {settings_.popping_charge, extent_, &neighbours_};
  }
  if (charge_px) {
    charge.per_px = settings_.view_popping_charge;
    charge.view = &*view;
  }
  rank_candidates(snapshot_, saliency_, 2 * settings_.max_ops_per_step, evaluation_, charge,
                  {settings_.interface_charge, interface_weights_, settings_.pin_level_pull, budget_level_});
  evaluation_ms_ = ms_since(t0);
}

bool SaliencyController::budget_demand(BudgetDemand& out) const {
  out.reserve = budget_reserve(budget(), settings_.max_ops_per_step);
  if (!evaluation_ready_ || job_running_ || evaluation_.snapshot_step != boundary_ - 1) return false;
  out.refine.clear();
  out.coarse.clear();
  for (const Candidate& c : evaluation_.refine) out.refine.push_back(c.priority);
  for (const Candidate& c : evaluation_.coarse) out.coarse.push_back(c.priority);
  return true;
}

void SaliencyController::set_budget(int nodes) {
  if (nodes < 1) throw std::invalid_argument("set_budget: the node budget must be >= 1");
  pending_budget_ = nodes;
}

void SaliencyController::set_spectator(const Spectator& spectator) {
  if (!settings_.view)
    throw std::logic_error("set_spectator: the controller was made without view terms (FeedbackSettings::view)");
  validate_spectator(spectator);  // every pose of its path, as the suite parser checks a suite's
  pending_spectator_ = spectator;
}

void SaliencyController::before_step(TcSoftBody& body) {
  const Clock::time_point t0 = Clock::now();
  // Run-time changes, here: no worker reads the controller's state between after_step and this boundary's post.
  if (pending_budget_) {
    if (*pending_budget_ < node_budget_) budget_state_.converged = false;  // it may coarsen past it on the way down
    node_budget_ = *pending_budget_;
    time_budget_ = settings_.max_step_ms > 0 ? std::min(time_budget_, node_budget_) : node_budget_;
    pending_budget_.reset();
  }
  if (pending_spectator_) {
    spectator_ = std::move(pending_spectator_);
    pending_spectator_.reset();
  }
  if (settings_.max_step_ms > 0) adapt_time_budget();
  // The evaluation from the previous boundary, joined already in parallel mode.
  double worker_ms = 0;
  if (evaluation_ready_ && evaluation_.snapshot_step == boundary_ - 1) {
    apply_evaluation(body, evaluation_, budget(), settings_, budget_state_);
    if (workers_) worker_ms = evaluation_ms_;
  } else if (!budget_state_.converged && body.node_count() <= budget()) {
    budget_state_.converged = true;
  }
  evaluation_ready_ = false;
  // TcSettings::exact_order: the operations advance_blends() ended and those just begun, in one restore, before the
  // snapshot below hands the cut to a worker.
  body.settle_order();
  if (boundary_ % settings_.evaluation_interval == 0) {
    extent_ = body.net().extent();
    if (settings_.interface_charge > 0 && settings_.interface_tension > 0 && interface_weights_.empty())
      interface_weights_ = interface_weights(body.tree(), settings_.interface_tension);  // once: O(N)
    budget_level_ = budget_level(body.tree(), budget());  // the budget may move (max_step_ms)
    const bool positions = settings_.illumination || settings_.popping_charge > 0 || spectator_.has_value();
    take_snapshot(body, cut_view(body), positions, boundary_, snapshot_,
                  settings_.contact_saliency > 0 ? &contacts_ : nullptr);
    if (occlusion_cell_px() > 0)
      occlusion_.capture(body, snapshot_);  // here, where the cut holds still; drawn on the worker
    else
      snapshot_.faces.clear();
    if (workers_) {
      workers_->post([this] { evaluate(); });
      job_running_ = true;
    } else {
      evaluate();
    }
    evaluation_ready_ = true;
  }
  ++boundary_;
  cost_.critical_ms = ms_since(t0);
  cost_.total_ms = cost_.critical_ms + worker_ms;
}

void SaliencyController::after_step(const TcSoftBody& body) {
  // The step's contacts, by tree node: their Bullet node pointers hold only until the next boundary's operations.
  if (settings_.contact_saliency > 0) nodes_in_contact(body, body.tree_ids(), contacts_);
  if (!job_running_) return;
  // The worker read the cut in place; join it before the next boundary may change the cut.
  const Clock::time_point t0 = Clock::now();
  job_running_ = false;
  workers_->wait();  // rethrows what the evaluation threw: the error reaches the simulation thread here
  const double waited = ms_since(t0);
  cost_.critical_ms += waited;
  cost_.total_ms += waited;
}

void SaliencyController::pause() {
  if (workers_) workers_->park();
  // Other bodies step until resume(): that gap is no step period of this body's, so the time budget forgets it.
  last_boundary_ = {};
}

void SaliencyController::resume() {
  if (workers_) workers_->wake();
}

void SaliencyController::adapt_time_budget() {
  // The step period (boundary to boundary) is the step time; an exponential average smooths the noise, and the
  // budget moves multiplicatively: down 3% while over the target, up 1% while clearly under it.
  const Clock::time_point now = Clock::now();
  if (last_boundary_ != Clock::time_point{}) {
    const double ms = std::chrono::duration<double, std::milli>(now - last_boundary_).count();
    step_ms_ema_ = step_ms_ema_ == 0 ? ms : 0.9 * step_ms_ema_ + 0.1 * ms;
    if (step_ms_ema_ > settings_.max_step_ms)
      time_budget_ = std::max(16, static_cast<int>(time_budget_ * 0.97));
    else if (step_ms_ema_ < 0.9 * settings_.max_step_ms)
      time_budget_ = std::min(node_budget_, static_cast<int>(time_budget_ * 1.01) + 1);
  }
  last_boundary_ = now;
}

}  // namespace tcsb
