#include "feedback/controller.h"

#include <stdexcept>

#include "feedback/random_controller.h"
#include "feedback/saliency_controller.h"

namespace tcsb {

void Controller::set_budget(int) { throw std::logic_error("Controller::set_budget: this controller has no budget"); }

void Controller::set_spectator(const Spectator&) {
  throw std::logic_error("Controller::set_spectator: this controller has no view terms");
}

bool Controller::budget_demand(BudgetDemand&) const { return false; }

std::unique_ptr<Controller> make_controller(const FeedbackSettings& settings, int target_nodes, std::uint64_t seed,
                                            const std::optional<Spectator>& spectator) {
  check_feedback_settings(settings);  // evaluation_interval 0 was a SIGFPE at the first step
  if (settings.view && settings.policy == PolicyKind::kSaliency && !spectator)
    throw std::invalid_argument("feedback.view: the view terms need a camera");
  if (settings.view && spectator) validate_spectator(*spectator);  // a pose with no image would stop the run mid-way
  switch (settings.policy) {
    case PolicyKind::kRandom: return std::make_unique<RandomController>(target_nodes, settings.max_ops_per_step, seed);
    case PolicyKind::kSaliency:
      return std::make_unique<SaliencyController>(settings, target_nodes,
                                                  settings.view ? spectator : std::optional<Spectator>{});
  }
  return nullptr;
}

}  // namespace tcsb
