// The "op_work" object of a TC-SB case in the native result JSON: per operation, the number of calls (all, and
// interior) and, per OpWork count, the largest and the mean count of one call and the mean over interior calls
// (paper/op_work.h).
#pragma once

#include <nlohmann/json.hpp>
#include <span>

#include "softbody/op_sample.h"

namespace tcsb {

/// {"refine": {"calls": 120, "interior_calls": 80, "nodes": {"max": 18, "mean": 15.2, "interior_mean": 16.1},
/// "links": ..., "tree_records": ..., "dbvt_leaves": ..., "relocation_nodes": ..., "relocation_links": ...,
/// "dbvt_ancestors": ...}, "end-refine": ..., "coarse": ..., "end-coarse": ...}. An operation that was never called
/// has calls 0 and null maxima and means; one never called in the interior has null interior means.
nlohmann::ordered_json op_work_json(std::span<const OpSample> samples);

}  // namespace tcsb
