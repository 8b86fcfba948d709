// The suite's "fidelity" block: whether the fidelity pass runs, which extra bodies it adds (Pareto targets,
// ablations, the error-against-time curves) and the calibration it reads. Its own file: the suite reader stays the
// reader of the suite's shape.
#pragma once

#include "suite/suite_fields.h"

namespace tcsb {

/// Reads root's "fidelity" (absent: no fidelity pass) into s.fidelity. Throws InputError naming the field.
void parse_fidelity(const suite_fields::Reader& r, const suite_fields::Object& root, Suite& s);

}  // namespace tcsb
