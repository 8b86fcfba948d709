// The converged reference of the compliant material: the full-resolution body whose small steps no longer change
// the cloth. Bullet's model has no such reference (more iterations make another, stiffer cloth); the compliant
// material converges to one cloth as its small steps shrink, and every subject of a compliant suite — TC-SB, the
// uniform grids, the full-resolution body at the suite's small steps, stock Bullet — is measured against it.
#pragma once

#include <memory>
#include <vector>

#include "fidelity/fidelity_result.h"
#include "net/net.h"
#include "suite/suite.h"

namespace tcsb {

/// The most doublings of the suite's small steps the search tries (the reference then steps with at most 8 x the
/// suite's): each costs about four times the last, and the fidelity pass runs at the end of every scene suite.
inline constexpr int kMaxReferenceDoublings = 3;

/// From the suite's small steps on, doubles them until doubling moves the full-resolution surface less than the
/// noise floor, over the suite's steps (the same measured steps the subjects are compared on), at most
/// kMaxReferenceDoublings times: the count whose doubling stayed under the floor, or the last one tried, not
/// converged. Only for a compliant suite.
ReferenceSubsteps find_reference_substeps(const Suite& suite, const std::shared_ptr<const Net>& net,
                                          std::size_t net_index);

}  // namespace tcsb
