// Controller: decides at each step boundary which TreeCut operations a TC-SB body begins, under its budget.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "../feedback/feedback_settings.h"
#include "../feedback/world_budget.h"
#include "../softbody/tc_softbody.h"
#include "../view/camera.h"

namespace tcsb {

/// What the feedback stage cost in one step, milliseconds.
struct FeedbackCost {
  double critical_ms = 0;  ///< time the simulation thread spent on feedback (waiting included)
  double total_ms = 0;     ///< all feedback work, worker threads included
};

/// The controller of the paper's Figure 1: issues refine/coarse operations based on the feedback stage.
class Controller {
 public:
  virtual ~Controller() = default;
  /// Called once per step boundary, after the body's blends advanced and before Bullet steps; begins operations.
  virtual void before_step(TcSoftBody& body) = 0;
  /// Called right after Bullet stepped (a parallel controller snapshots the state here).
  virtual void after_step(const TcSoftBody& body) {}
  /// The body will not step for a while (the fidelity pass steps other bodies in between): a parallel controller
  /// lets its worker sleep now instead of spinning for the next job, so it does not take a core from them; a time
  /// budget does not count the pause as a step.
  virtual void pause() {}
  /// The body steps again after a pause(): a parallel controller wakes its worker before the next step.
  virtual void resume() {}
  /// Cost of the last step's feedback work.
  virtual FeedbackCost last_cost() const { return {}; }
  /// Changes the node budget of a running controller, effective at the next step boundary (before_step): a lower
  /// budget coarsens the body down to it, a higher one lets it refine. Throws std::invalid_argument when `nodes` < 1,
  /// std::logic_error when the controller has no budget to change (this default).
  virtual void set_budget(int nodes);
  /// Changes whom the view terms see through (camera pose, field of view, image size; FeedbackSettings::view),
  /// effective at the next evaluation; safe while a parallel controller's worker evaluates the last one. A fixed camera
  /// (an empty path) is seen where it stands whatever the time; a path's time is the controller's step boundaries x
  /// spectator.dt. Throws std::invalid_argument for a camera that gives no image (camera_pose_problem, a field of view
  /// outside (0, 180), an image of no pixels), std::logic_error when the controller has no view terms (this default,
  /// and a saliency controller made without FeedbackSettings::view).
  virtual void set_spectator(const Spectator& spectator);
  /// The priorities of the candidates the next before_step will choose from (BudgetDemand's refine and coarse; the
  /// caller fills in the body's node counts) and the nodes its policy keeps free below its budget (reserve, set even
  /// when it returns false), for a world budget to weigh this body against others (feedback/world_budget.h). Call
  /// between after_step and before_step. False when the controller ranks nothing this boundary (this default, and a
  /// controller between evaluations); the candidates are then left as they were.
  virtual bool budget_demand(BudgetDemand& out) const;
};

/// The controller a suite asks for, holding the body near `target_nodes`. `seed` makes random choices repeatable.
/// `spectator`: whom the view terms (settings.view) see through; required with them, ignored without. Throws
/// std::invalid_argument naming the field for settings no feedback stage can run with (check_feedback_settings),
/// settings.view without a spectator, or a spectator that gives no image (validate_spectator).
std::unique_ptr<Controller> make_controller(const FeedbackSettings& settings, int target_nodes, std::uint64_t seed,
                                            const std::optional<Spectator>& spectator = std::nullopt);

}  // namespace tcsb
