#include "feedback/controller.h"

#include <stdexcept>

#include "feedback/random_controller.h"
#include "feedback/saliency_controller.h"

namespace tcsb {

void Controller::set_budget(int) { throw std::logic_error("Controller::set_budget: this controller has no budget"); }

void Controller::set_spectator(const Spectator&) {
  throw std::logic_error("Controller::set_spectator: this controller has no view terms");
}

void check_spectator(const Spectator& spectator) {
  const Camera& c = spectator.camera;
  const auto pose_ok = [&](const CameraPose& pose) {
    switch (camera_pose_problem(pose, c.up)) {
      case CameraPoseProblem::kNone: return;
      case CameraPoseProblem::kNoDirection:
        throw std::invalid_argument("set_spectator: the camera's position equals its target");
      case CameraPoseProblem::kLooksAlongUp:
        throw std::invalid_argument("set_spectator: the camera looks along its up direction");
    }
  };
  if (c.path.empty()) pose_ok(c.pose);
  for (const CameraKey& key : c.path) pose_ok(key.pose);
  for (std::size_t i = 1; i < c.path.size(); ++i)
    if (!(c.path[i].time > c.path[i - 1].time))
      throw std::invalid_argument("set_spectator: the camera path's times must be strictly ascending");
  if (!(c.fov_deg > 0 && c.fov_deg < 180))
    throw std::invalid_argument("set_spectator: the field of view must lie in (0, 180) degrees");
  if (c.width_px < 1 || c.height_px < 1) throw std::invalid_argument("set_spectator: the image must have pixels");
  if (!(spectator.dt > 0)) throw std::invalid_argument("set_spectator: the step length dt must be > 0");
}

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
