// Bootstrap intervals for claims measured by a run: resample the repetitions, recompute the claims, and read off
// where each measured value could lie had the run been repeated. On this shared 2-core VM a verdict near its
// threshold can flip from run to run; the interval says whether this run's verdict is decided or within its noise.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "analysis/claim.h"
#include "run/run_result.h"

namespace tcsb {

/// Fewer repetitions than this and resampling them says nothing about the noise (one repetition would give a
/// point "interval", falsely decided): no intervals then.
inline constexpr std::size_t kMinRepetitionsForIntervals = 5;

/// One bootstrap resample of a run's repetitions. For each net, repetition indices are drawn once — the processes
/// that measured them first (RepetitionResult::process: a merged result's shards), then repetitions within them, by
/// resample_grouped(); with one process simply repetitions with replacement — and used for every case of that net,
/// so runs measured side by side (plain and TC-SB of one repetition) stay paired. With Suite::interleave_across_nets
/// every net's cases of a repetition ran together, so the indices are drawn once for all nets — when every case has
/// its repetitions in the same processes, as the runner and the split by repetition give; otherwise per net. Each
/// case keeps the drawn
/// repetitions, renumbered 0..R-1, with their operation samples, and its summary is recomputed. Step series and the
/// fidelity pass are not carried over (nothing the tables or claims read). Throws std::logic_error if a net's cases
/// differ in repetition count or processes, or a case's operation samples do not add up to its repetitions' counts (the
/// runner never produces either).
RunResult resample_repetitions(const RunResult& result, std::mt19937_64& rng);

/// The run restricted to the cases `case_indices` (kept in case order), without per-step series or the fidelity
/// pass, and — unless `keep_operations` — without operation samples (a repetition then records 0 operations): what
/// a bootstrap needs to recompute the claims on those cases, and no more, since it copies the run once per resample.
RunResult subset_for_bootstrap(const RunResult& result, const std::vector<std::size_t>& case_indices,
                               bool keep_operations);

/// Claim id -> its measured value on each resample (NaN where a resample leaves it unmeasured).
using ClaimReplicates = std::map<std::string, std::vector<double>>;

/// Recomputes `claims_of` on `resamples` resamples of `result` drawn from a generator seeded with `seed`. Empty
/// when some case has fewer than kMinRepetitionsForIntervals repetitions. (Pass a subset_for_bootstrap() of the run
/// to resample only the cases the claims read: much faster.)
ClaimReplicates bootstrap_claims(const RunResult& result,
                                 const std::function<std::vector<Claim>(const RunResult&)>& claims_of, int resamples,
                                 std::uint64_t seed);

/// Sets each claim's interval to the central `confidence` percentile interval of its replicates (matched by id);
/// claims without replicates, or undefined on too many resamples, keep none.
void attach_intervals(std::vector<Claim>& claims, const ClaimReplicates& replicates, double confidence);

}  // namespace tcsb
