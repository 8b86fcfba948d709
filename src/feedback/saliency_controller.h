// SaliencyController: the paper's feedback loop (Figure 1). At a step boundary it copies the nodes' motion and
// evaluates saliency and priorities — on worker threads in parallel mode, overlapping the Bullet step — and at the
// next boundary the controller applies the ranked operations under the budgets.
//
// Determinism: the evaluation taken at boundary b is applied at boundary b+1 in both modes, and it reads the cut
// as it stands after b's operations; the worker is joined before the body's cut can change again. Synchronous and
// parallel runs, with any thread count, therefore make the same decisions and give bit-identical results. (Only
// the optional time budget reads a clock, and is therefore not repeatable.)
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <vector>

#include "../feedback/budget_policy.h"
#include "../feedback/controller.h"
#include "../feedback/cut_snapshot.h"
#include "../feedback/evaluator.h"
#include "../feedback/feedback_workers.h"
#include "../feedback/saliency.h"
#include "../feedback/surface_occlusion.h"

namespace tcsb {

/// Budget-holding controller driven by the BSWDF motion saliency.
class SaliencyController final : public Controller {
 public:
  /// `node_budget`: the maximal number of simulated (Bullet) nodes, held at every step once first reached.
  /// `spectator`: with one, saliency takes the BSWDF's view terms through its camera (settings.view); when the camera
  /// models occlusion (occlusion_cell_px > 0), nodes the body's own surface hides from it get saliency 0.
  SaliencyController(const FeedbackSettings& settings, int node_budget,
                     std::optional<Spectator> spectator = std::nullopt);
  ~SaliencyController() override;

  void before_step(TcSoftBody& body) override;
  void after_step(const TcSoftBody& body) override;
  FeedbackCost last_cost() const override { return cost_; }
  void pause() override;
  void resume() override;
  /// Effective at the next before_step(). Lowering it below the body's size lets the body coarsen past the budget
  /// once more (as before its first convergence), so it comes down to it.
  void set_budget(int nodes) override;
  /// Effective at the next evaluation (taken in before_step, after any worker joined). Requires settings.view.
  void set_spectator(const Spectator& spectator) override;
  /// The evaluation taken at the last boundary, once after_step has joined it.
  bool budget_demand(BudgetDemand& out) const override;

  /// The budget in force now: the node budget, lowered by the time budget when one is set.
  int budget() const;
  /// True once the body first fitted the budget; from then on no operation may exceed it.
  bool converged() const { return budget_state_.converged; }

 private:
  void evaluate();
  void adapt_time_budget();
  /// The spectator's occlusion cells, pixels; 0 without a spectator or when its camera does not model occlusion.
  int occlusion_cell_px() const { return spectator_ ? spectator_->camera.occlusion_cell_px : 0; }

  FeedbackSettings settings_;
  std::optional<Spectator> spectator_;
  /// set_budget()'s and set_spectator()'s values, taken at the next before_step (a worker may read spectator_ now).
  std::optional<int> pending_budget_;
  std::optional<Spectator> pending_spectator_;
  int node_budget_;
  int time_budget_;  // adapted when settings_.max_step_ms > 0
  BudgetState budget_state_;
  std::int64_t boundary_ = 0;  // step boundaries seen
  CutSnapshot snapshot_;
  NeighbourSums sums_;
  CutNeighbours neighbours_;              // for the popping charge
  std::vector<TreeId> contacts_;          // nodes in contact after the last step, for the contact feature
  double extent_ = 1;                     // the net's, for the popping charge
  std::vector<float> interface_weights_;  // per tree node, when the interface charge weighs the pins' tension
  int budget_level_ = 0;                  // the level most of the cloth takes under the budget, for the pull
  std::vector<float> saliency_;
  std::vector<float> ahead_;    ///< with view_lookahead_s: the saliency as the spectator will see the cloth
  SurfaceOcclusion occlusion_;  // when the spectator's camera models occlusion: its depth buffer, kept between steps
  Evaluation evaluation_;
  bool evaluation_ready_ = false;
  double evaluation_ms_ = 0;  // time of the last evaluation, wherever it ran
  std::unique_ptr<FeedbackWorkers> workers_;
  bool job_running_ = false;
  FeedbackCost cost_;
  std::chrono::steady_clock::time_point last_boundary_{};
  double step_ms_ema_ = 0;
};

}  // namespace tcsb
