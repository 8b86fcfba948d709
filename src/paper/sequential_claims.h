// Claims judged in looks: the run's own repetitions are the first look; a claim the run cannot decide gets more
// repetitions of exactly the cases it is measured from (beside their plain baseline), and is judged again at a
// stricter level (analysis/sequential_looks.h), until every claim of the paper is decided, the looks run out, or
// the wall-time budget would be overrun. A claim decided at one look keeps that verdict.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/claim.h"
#include "analysis/sequential_looks.h"
#include "paper/claim_scope.h"
#include "run/run_result.h"

namespace tcsb {

/// A claim followed through the looks.
struct TrackedClaim {
  Claim claim;                      ///< value and interval of its last look
  bool gates = true;                ///< a claim of the paper (decides the exit code), not a project target
  std::optional<ClaimScope> scope;  ///< the cases it is measured from; nullopt: not judged on an interval
  int look = 0;                     ///< the look of its verdict (decided there, or the last it was judged at); 0: none
  int repetitions = 0;              ///< repetitions of each case in its scope at that look
  std::size_t processes = 0;        ///< processes whose repetitions its interval pooled at that look (0: none)
  double confidence = 0;            ///< its interval's confidence (0: no look judged it)
};

/// One look at the undecided claims.
struct Look {
  int look = 1;           ///< 1: the run's own repetitions
  int extra = 0;          ///< repetitions added to each case in `cases` before this look (0 at look 1)
  std::size_t cases = 0;  ///< cases that ran the extra repetitions (0 at look 1)
  int repetitions = 0;    ///< repetitions per case behind this look's intervals (the most among its cases)
  double confidence = 0;  ///< of this look's intervals
  int resamples = 0;      ///< bootstrap resamples behind them
  int judged = 0;         ///< claims and targets judged at this look
  int undecided = 0;      ///< claims of the paper still undecided after it
  double seconds = 0;     ///< wall time of the look: its extra repetitions and its intervals
};

/// How the looks proceed.
struct SequentialSettings {
  double alpha = kSequentialAlpha;  ///< error rate over all looks, per claim
  int max_looks = 5;                ///< look 5 needs 6 400 resamples (look_resamples): the bootstrap's cost bound
  /// Wall time for the looks, counted from the start of the first (always taken: its intervals are part of it); a
  /// look after it is taken only if it is predicted to end within this. 0: the first look only.
  double budget_s = 0;
  std::uint64_t seed = 1;  ///< bootstrap seed of look 1 (look k uses seed + k - 1)
};

/// The claims judged on one state of a run.
struct JudgedClaims {
  std::vector<Claim> claims;   ///< the paper's claims (gating)
  std::vector<Claim> targets;  ///< the project's targets (reported)
};

/// What the looks need from the outside world; injected so tests can fake the runner and the clock.
struct SequentialHooks {
  /// The paper's claims (gating) and the project's targets (reported) on a run, from one computation of its tables
  /// (it runs once per bootstrap resample).
  std::function<JudgedClaims(const RunResult&)> claims_of;
  std::function<std::optional<ClaimScope>(std::string_view)> scope_of;  ///< cases behind a claim id
  /// Adds `extra` repetitions of the cases (run_more_repetitions in production).
  std::function<void(RunResult&, const std::vector<std::size_t>&, int)> run_more;
  std::function<double()> now_s;             ///< monotonic seconds
  std::function<void(const Look&)> on_look;  ///< told after each look (progress); may be empty
};

/// Why the looks ended.
enum class LooksEnded {
  kDecided,   ///< every claim of the paper is decided
  kBudget,    ///< another look would not fit in the budget (also: budget 0)
  kMaxLooks,  ///< the last look allowed was taken
};

/// The outcome of the looks.
struct SequentialOutcome {
  std::vector<TrackedClaim> claims;   ///< the paper's claims, in claims_of order
  std::vector<TrackedClaim> targets;  ///< the project's targets, in claims_of order
  std::vector<Look> looks;
  double bootstrap_s = 0;  ///< of which computing intervals
  LooksEnded ended = LooksEnded::kDecided;
};

/// Runs the looks on `result`, adding repetitions to it. Extra repetitions per look: as many as the cases already
/// have (doubling them), fewer if the budget allows fewer but at least half as many; none when not even that fits
/// (predicted from the cases' own step times, with 25 % to spare, plus the bootstrap's measured cost per resample).
SequentialOutcome judge_sequentially(RunResult& result, const SequentialSettings& settings,
                                     const SequentialHooks& hooks);

/// Predicted wall time of one more repetition of each of `cases`: per case, its mean build time plus its warm-up
/// and timed steps at its mean step time.
double repetition_cost_s(const RunResult& result, const std::vector<std::size_t>& cases);

/// Stable name for reports: "decided", "budget" or "max_looks".
const char* looks_ended_name(LooksEnded ended);

}  // namespace tcsb
