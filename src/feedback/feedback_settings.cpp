#include "feedback/feedback_settings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tcsb {

const char* policy_name(PolicyKind policy) { return policy == PolicyKind::kSaliency ? "saliency" : "random"; }

namespace {

[[noreturn]] void refuse(const char* field, const std::string& need, double got) {
  std::ostringstream text;
  text << "FeedbackSettings: " << field << " must be " << need << ", got " << got;
  throw std::invalid_argument(text.str());
}

void non_negative(const char* field, double value) {
  if (!(std::isfinite(value) && value >= 0)) refuse(field, "a finite number >= 0", value);
}

void positive(const char* field, double value) {
  if (!(std::isfinite(value) && value > 0)) refuse(field, "a finite number > 0", value);
}

void unit(const char* field, double value) {
  if (!(value >= 0 && value <= 1)) refuse(field, "in [0, 1]", value);
}

}  // namespace

void check_feedback_settings(const FeedbackSettings& s) {
  if (s.policy != PolicyKind::kSaliency && s.policy != PolicyKind::kRandom)
    refuse("policy", "kSaliency or kRandom", static_cast<double>(s.policy));
  non_negative("threshold", s.threshold);
  if (s.max_ops_per_step < 1) refuse("max_ops_per_step", ">= 1", s.max_ops_per_step);
  if (s.evaluation_interval < 1)
    refuse("evaluation_interval", ">= 1 (evaluate every this many steps)", s.evaluation_interval);
  positive("global_motion_scale", s.global_motion_scale);
  for (const double c : s.light_direction)
    if (!std::isfinite(c)) refuse("light_direction", "finite", c);
  if (s.light_direction[0] == 0 && s.light_direction[1] == 0 && s.light_direction[2] == 0)
    throw std::invalid_argument("FeedbackSettings: light_direction must not be the zero vector");
  if (s.threads < 1 || s.threads > 64) refuse("threads", "in [1, 64]", s.threads);
  non_negative("max_step_ms", s.max_step_ms);
  non_negative("popping_charge", s.popping_charge);
  non_negative("interface_charge", s.interface_charge);
  non_negative("interface_tension", s.interface_tension);
  non_negative("pin_level_pull", s.pin_level_pull);
  unit("contact_saliency", s.contact_saliency);
  positive("view_motion_scale", s.view_motion_scale);
  positive("view_detail_px", s.view_detail_px);
  unit("view_static_share", s.view_static_share);
  unit("view_offscreen_share", s.view_offscreen_share);
  non_negative("view_lookahead_s", s.view_lookahead_s);
  non_negative("view_popping_charge", s.view_popping_charge);
}

}  // namespace tcsb
