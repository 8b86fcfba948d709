#include "world/world_frames.h"

#include <algorithm>
#include <stdexcept>

#include "suite/scene_bodies.h"
#include "world/world_runner.h"

namespace tcsb {

namespace {

/// Keeps the recorded methods' scenes at the requested steps, as the pass hands them over (method by method within
/// each block of steps).
class WorldFrameRecorder final : public WorldObserver {
 public:
  WorldFrameRecorder(std::vector<std::string> methods, const std::vector<int>& steps) : methods_(std::move(methods)) {
    for (const int step : steps) frames_.push_back({step, std::vector<WorldFrameScene>(methods_.size())});
  }

  bool wants(const std::string& method, int steps) const override {
    return method_index(method) < methods_.size() && frame_index(steps) < frames_.size();
  }

  void observe(const WorldStepView& view) override {
    WorldFrameScene& scene = frames_[frame_index(view.steps)].scenes[method_index(view.method)];
    scene.nodes = view.nodes;
    scene.surfaces.assign(view.surfaces.begin(), view.surfaces.end());
    scene.levels.assign(view.levels.begin(), view.levels.end());
  }

  /// The frames every method reached: a diverged method's last frames are missing, and so are the others' then.
  std::vector<WorldFrame> complete_frames() && {
    std::vector<WorldFrame> out;
    for (WorldFrame& f : frames_) {
      const bool complete =
          std::all_of(f.scenes.begin(), f.scenes.end(), [](const WorldFrameScene& s) { return !s.surfaces.empty(); });
      if (!complete) break;
      out.push_back(std::move(f));
    }
    return out;
  }

 private:
  std::size_t method_index(const std::string& method) const {
    return static_cast<std::size_t>(std::find(methods_.begin(), methods_.end(), method) - methods_.begin());
  }
  /// The frame recorded after `steps` steps, or frames_.size() when none is.
  std::size_t frame_index(int steps) const {
    const auto it =
        std::lower_bound(frames_.begin(), frames_.end(), steps, [](const WorldFrame& f, int s) { return f.step < s; });
    return it != frames_.end() && it->step == steps ? static_cast<std::size_t>(it - frames_.begin()) : frames_.size();
  }

  std::vector<std::string> methods_;
  std::vector<WorldFrame> frames_;
};

}  // namespace

std::vector<std::string> world_frame_methods(const Suite& suite) {
  return {suite.feedback.budget_scope == BudgetScope::kWorld ? "tcsb_world" : "tcsb_body", "discrete_lod"};
}

WorldFrames record_world_frames(const Suite& suite, double compression, const std::vector<int>& steps) {
  if (!is_world_suite(suite)) throw std::invalid_argument("record_world_frames: the suite has no scene.bodies");
  if (!(compression > 0 && compression < 1)) throw std::invalid_argument("record_world_frames: compression");
  const int total = suite.warmup_steps + suite.steps;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i] < 0 || steps[i] > total || (i > 0 && steps[i] <= steps[i - 1]))
      throw std::invalid_argument("record_world_frames: steps must be ascending, distinct and within the run");
  }
  // The pass at this one budget alone, without the curves' budgets and passes: each budget's methods step in worlds
  // of their own, so the others change nothing of these (and two budgets' scenes would share a method's name).
  Suite one_budget = suite;
  one_budget.compression = {compression};
  one_budget.fidelity.curves.reset();
  const std::vector<std::string> methods = world_frame_methods(suite);
  WorldFrameRecorder recorder(methods, steps);
  const WorldResult result = run_world(one_budget, &recorder);

  WorldFrames out;
  out.compression = compression;
  out.bodies = scene_body_nets(suite);
  for (const std::string& method : methods)
    for (const WorldMethodResult& m : result.methods)
      if (m.method == method) out.methods.push_back(m);
  out.frames = std::move(recorder).complete_frames();
  return out;
}

}  // namespace tcsb
