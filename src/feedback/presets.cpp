#include "feedback/presets.h"

namespace tcsb {

namespace {

/// What every preset shares: the suites' TC-SB and feedback for converged cloth.
Preset common(int piterations) {
  Preset p;
  p.solver.piterations = piterations;
  p.tcsb.blend_steps = 4;
  p.tcsb.placement = Placement::kAffine;
  p.tcsb.interfaces = Interfaces::kHanging;
  p.tcsb.masses = Masses::kCut;
  p.tcsb.exact_order = true;
  p.feedback.threshold = 0.3;
  p.feedback.max_ops_per_step = 256;
  p.feedback.evaluation_interval = 4;
  p.feedback.parallel = true;
  p.feedback.threads = 1;
  p.lod_rest = RestPlacement::kVertex;
  return p;
}

}  // namespace

Preset hanging_cloth_preset() {
  Preset p = common(32);
  p.feedback.interface_charge = 3;
  p.feedback.interface_tension = 0.5;
  p.feedback.pin_level_pull = 8;
  return p;
}

Preset drape_preset() {
  Preset p = common(16);
  p.feedback.contact_saliency = 0.1;
  p.feedback.interface_charge = 3;
  return p;
}

Preset flag_preset() {
  Preset p = common(16);
  p.feedback.parallel = false;
  return p;
}

Preset close_up_preset() {
  Preset p = hanging_cloth_preset();
  p.feedback.view = true;
  p.feedback.view_motion_scale = 20;
  p.feedback.view_detail_px = 8;
  p.feedback.view_static_share = 0.001;
  return p;
}

}  // namespace tcsb
