// Whether two result files hold measurements of one process. Pooling runs (`tcsb tax`) counts each process once:
// a copy of a run with its date or wall time edited, or a merged result beside one of its own shards, would count
// the same repetitions twice and narrow the interval as if they had been measured again. File names, paths and
// timestamps cannot tell; the measurements can: two processes never time a case's repetitions to the same doubles.
#pragma once

#include <string>

#include "result/result_view.h"

namespace tcsb {

/// "" when `a` and `b` share no measurement; else where they do, as "case LABEL has the same N repetition time(s),
/// M in all": the first case with repetitions (of one number and the very same mean step time) in both. Repetition
/// by repetition, so a shard split by repetitions is found beside the result merged from it; two shared repetitions
/// make one process (or one, when that is all the smaller file could share), a single one alike may be chance.
std::string shared_measurement(const ResultView& a, const ResultView& b);

}  // namespace tcsb
