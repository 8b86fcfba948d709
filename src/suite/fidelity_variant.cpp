#include "suite/fidelity_variant.h"

#include <array>
#include <stdexcept>

namespace tcsb {

namespace {

struct FidelityVariant {
  std::string_view name;
  BodySpec body;  ///< at compression 1; fidelity_subject() sets the budget
};

BodySpec tcsb_variant() { return {.kind = BodyKind::kTcsb}; }
BodySpec uniform_variant() { return {.kind = BodyKind::kUniform}; }
BodySpec calibrated_variant(BodySpec spec) {
  spec.calibration = BodyCalibration::kSuite;
  return spec;
}
BodySpec motion_only_variant(BodySpec spec) {
  spec.view_terms = false;
  return spec;
}

/// Every variant, in the order their seeds were first numbered: append, never reorder (fidelity_variant_index).
const std::array<FidelityVariant, 13>& fidelity_variants() {
  static const std::array<FidelityVariant, 13> variants = [] {
    BodySpec random = tcsb_variant(), rigid = tcsb_variant(), no_geomorph = tcsb_variant(),
             fans = calibrated_variant(tcsb_variant());
    random.policy = PolicyKind::kRandom;
    rigid.placement = Placement::kRigid;
    no_geomorph.geomorph = false;
    fans.interfaces = Interfaces::kLinks;  // the paper's fans, in a suite whose TC-SB uses hanging interfaces
    BodySpec stock = uniform_variant();    // a uniform grid of every node: the plain body, stepped by Bullet itself
    stock.stock_solver = true;
    return std::array<FidelityVariant, 13>{{
        {"tcsb", tcsb_variant()},
        {"uniform_grid", uniform_variant()},
        {"switch_body", {.kind = BodyKind::kSwitch}},
        {"tcsb_random", random},
        {"tcsb_rigid", rigid},
        {"tcsb_no_geomorph", no_geomorph},
        {"tcsb_calibrated", calibrated_variant(tcsb_variant())},
        {"uniform_grid_calibrated", calibrated_variant(uniform_variant())},
        {"tcsb_calibrated_fans", fans},
        {"tcsb_motion_only", motion_only_variant(tcsb_variant())},
        {"tcsb_calibrated_motion_only", motion_only_variant(calibrated_variant(tcsb_variant()))},
        {"stock_bullet", stock},
        // full resolution with its link passes divided (fidelity_subject's solver_divisor): the third curve of error
        // against time, what a user who wants a cheaper cloth without adaptivity would try
        {"full_resolution", uniform_variant()},
    }};
  }();
  return variants;
}

}  // namespace

int fidelity_variant_index(std::string_view method) {
  const auto& variants = fidelity_variants();
  for (std::size_t i = 0; i < variants.size(); ++i)
    if (variants[i].name == method) return static_cast<int>(i);
  throw std::invalid_argument("fidelity: no variant is named \"" + std::string(method) + "\"");
}

FidelitySubjectSpec fidelity_subject(std::string_view method, double compression, int solver_divisor) {
  FidelitySubjectSpec spec{std::string(method), fidelity_variants()[fidelity_variant_index(method)].body};
  spec.body.compression = compression;
  spec.body.solver_divisor = solver_divisor;
  return spec;
}

}  // namespace tcsb
