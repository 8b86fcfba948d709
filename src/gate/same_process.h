// Whether two result files hold measurements of one process. Pooling runs (`tcsb tax`) counts each process once:
// a copy of a run with its date or wall time edited, or a merged result beside one of its own shards, would count
// the same repetitions twice and narrow the interval as if they had been measured again. File names, paths and
// timestamps cannot tell; the measurements can: two processes never time a case's repetitions to the same doubles.
#pragma once

#include <string>

#include "result/result_view.h"

namespace tcsb {

/// "" when `a` and `b` share no measurement; else the first case (by label and configuration) that both hold with
/// the very same repetitions (numbers, statuses and mean step times, at least one of them timed), as
/// "case LABEL has the same N repetition times".
std::string shared_measurement(const ResultView& a, const ResultView& b);

}  // namespace tcsb
