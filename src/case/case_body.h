// CaseBody: the thing a case steps — one of the methods, behind one small interface, so the runner's timing loop
// is the same code for every method.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <memory>
#include <optional>

#include "case/body_factory.h"
#include "case/instruction_meter.h"
#include "feedback/controller.h"
#include "net/net.h"
#include "scene/scene_world.h"
#include "softbody/tc_softbody.h"
#include "suite/case_plan.h"
#include "suite/suite.h"

namespace tcsb {

/// The phases of a TC-SB step as its body timed them, milliseconds (operations included where they ran: end
/// operations in the blends, begun ones in the feedback stage).
struct StepPhases {
  double blends_ms = 0;    ///< advance_blends()
  double feedback_ms = 0;  ///< the controller before and after Bullet's step
  double bullet_ms = 0;    ///< the world's step
};

/// A body being simulated for a case, with whatever drives it.
class CaseBody {
 public:
  virtual ~CaseBody() = default;
  /// One whole step as timed: for TC-SB the blends, the feedback stage and its operations, then Bullet.
  virtual void step(btScalar dt) = 0;
  /// The Bullet body (for N, L, divergence checks and the state hash).
  virtual const btSoftBody& bullet() const = 0;
  /// Operations blending now (the paper's I); 0 for stock bodies.
  virtual int interpolations() const { return 0; }
  /// Feedback cost of the last step (zero for stock bodies).
  virtual FeedbackCost feedback_cost() const { return {}; }
  /// The phases of the last step, for a body that has them (TC-SB); a stock body's step is all Bullet's.
  virtual const StepPhases* phases() const { return nullptr; }
  /// The TC-SB body, if this is one.
  virtual TcSoftBody* tc() { return nullptr; }
  /// Counts the parts of each step with `meter` (`tcsb run --measure instructions`); nullptr (the default): not.
  void set_meter(InstructionMeter* meter) { meter_ = meter; }
  /// Other bodies step for a while (see Controller::pause()).
  virtual void pause() {}
  /// This body steps again (see Controller::resume()).
  virtual void resume() {}

 protected:
  /// Ends a part of the step on the meter, if the step is counted.
  void end_part(StepPart part) {
    if (meter_) meter_->end_part(part);
  }
  /// The run counts instructions (a meter is set).
  bool counting() const { return meter_ != nullptr; }

 private:
  InstructionMeter* meter_ = nullptr;
};

/// Node budget of a TC-SB or plain_equal case (node_budget), 0 for other methods.
int target_node_count(const Net& net, const CaseKey& key);

/// The description of a case's body: plain and stock Bullet on the net, Bullet's patch, plain_equal's uniform grid of
/// the budget (the fidelity pass's uniform_grid), or the suite's TC-SB at the budget.
BodySpec case_body_spec(const CaseKey& key);

/// Builds the body for a case (case_body_spec, make_body) inside `world` (which steps it; it must outlive the body).
/// `seed` drives any random choices (same seed, same run).
std::unique_ptr<CaseBody> make_case_body(const Suite& suite, const CaseKey& key, SceneWorld& world,
                                         std::shared_ptr<const Net> net, std::uint64_t seed);

}  // namespace tcsb
