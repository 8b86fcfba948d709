#include "feedback/tree_cut_driver.h"

namespace tcsb {

void TreeCutDriver::pre_tick() {
  if (controller_ && ticks_ > 0) controller_->after_step(body_);
  body_.advance_blends();
  if (controller_) controller_->before_step(body_);
  body_.refresh_faces();  // a stock world's solver does not: the faces must follow the cut before predictMotion
  ++ticks_;
}

void TreeCutDriver::callback(btDynamicsWorld* world, btScalar) {
  static_cast<TreeCutDriver*>(world->getWorldUserInfo())->pre_tick();
}

}  // namespace tcsb
