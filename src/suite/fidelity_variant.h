// Fidelity variants: the bodies the fidelity pass can run beside its reference, as data — a name, the one results
// carry, and a body description (suite/body_spec.h) — so a variant is a row of a table, not a branch of the factory.
#pragma once

#include <string>
#include <string_view>

#include "suite/body_spec.h"

namespace tcsb {

/// One body of the fidelity pass on every net: its name in results ("tcsb", "uniform_grid", "switch_body",
/// "tcsb_random", "tcsb_rigid", "tcsb_no_geomorph", "tcsb_calibrated", "uniform_grid_calibrated",
/// "tcsb_calibrated_fans", "tcsb_motion_only", "tcsb_calibrated_motion_only", "stock_bullet", "full_resolution"; "tcsb"
/// is the suite's TC-SB, uncalibrated: the timed one) and how it is built, its budget and solver divisor included.
struct FidelitySubjectSpec {
  std::string method;
  BodySpec body;
};

/// The fidelity variant named `method` at node budget `compression` (and, for full_resolution, link passes divided
/// by `solver_divisor`). Throws std::invalid_argument for a name that is none of the variants.
FidelitySubjectSpec fidelity_subject(std::string_view method, double compression, int solver_divisor = 1);

/// The variant's place in the list of variants, which has only grown since results were first written: part of a
/// subject's seed (fidelity_seed), so a variant keeps its random choices. Throws like fidelity_subject().
int fidelity_variant_index(std::string_view method);

}  // namespace tcsb
