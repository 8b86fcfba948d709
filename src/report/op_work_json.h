// The "op_work" object of a TC-SB case in the native result JSON: per operation, the number of calls and, per
// OpWork count, the largest and the mean count of one call (harness/op_work.h).
#pragma once

#include <nlohmann/json.hpp>
#include <span>

#include "softbody/op_sample.h"

namespace tcsb {

/// {"refine": {"calls": 120, "nodes": {"max": 18, "mean": 15.2}, "links": ..., "tree_records": ...,
/// "dbvt_leaves": ..., "dbvt_ancestors": ...}, "end-refine": ..., "coarse": ..., "end-coarse": ...}. An operation
/// that was never called has calls 0 and null maxima and means.
nlohmann::ordered_json op_work_json(std::span<const OpSample> samples);

}  // namespace tcsb
