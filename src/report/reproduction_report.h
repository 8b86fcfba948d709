// The reproduction: the paper's claims judged in looks (paper/sequential_claims.h) on a finished run, and its
// report — our Tables 1 and 2 beside the paper's, Figure 5's fits, the claims with their verdicts — as a JSON
// section appended to the native report, and as text for the console.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/claim.h"
#include "paper/paper_reference.h"
#include "paper/sequential_claims.h"
#include "run/run_result.h"

namespace tcsb {

/// How the claims are judged beyond the run's own repetitions.
struct ReproductionOptions {
  /// Wall time for judging the claims: the first look's intervals, then extra repetitions and their intervals while
  /// they fit (SequentialSettings::budget_s); 0: the run's repetitions only.
  double budget_s = 0;
  /// Told after each look (progress on the console); may be empty.
  std::function<void(const Look&)> on_look;
  /// Adds repetitions of chosen cases; empty: run_more_repetitions (tests inject a fake).
  std::function<void(RunResult&, const std::vector<std::size_t>&, int)> run_more;
};

/// A run checked against the paper.
struct Reproduction {
  PaperReference paper;
  std::vector<TrackedClaim> claims;   ///< the paper's claims (decide the exit code)
  std::vector<TrackedClaim> targets;  ///< this project's stricter targets (reported only)
  /// Sanity lines read off the claims (paper/paper_claims.h: nocompression_sanity); reported, never gating.
  std::vector<TrackedClaim> sanity;
  std::vector<Look> looks;                  ///< the looks taken, the first being the run's own repetitions
  LooksEnded ended = LooksEnded::kDecided;  ///< why the looks ended
  double budget_s = 0;                      ///< the budget the looks had
  double bootstrap_s = 0;                   ///< computing the claims' intervals, over all looks
  double wall_s = 0;  ///< the whole reproduction: the run, fidelity pass, extra repetitions, intervals
  /// Over the paper's claims: kFail if any failed, else kUndecided if any is undecided, else kPass.
  Verdict verdict() const;
};

/// Judges the paper's claims and the project's targets on a finished run, in looks: the claims its repetitions
/// cannot decide get extra repetitions of their cases (added to `result`) while the budget allows.
Reproduction check_reproduction(RunResult& result, PaperReference paper, const ReproductionOptions& options = {});

/// The `reproduction` section: side-by-side tables (paper, ours), Figure 5's fits, claims and targets (each with its
/// verdict, interval, look and repetitions), the looks, the overall verdict, wall time.
nlohmann::ordered_json reproduction_json(const RunResult& result, const Reproduction& reproduction);

/// Both tables side by side with the paper's, then every claim of the paper with its verdict; the project's own
/// targets too with `with_targets`, else one line saying where they are.
void print_reproduction(const RunResult& result, const Reproduction& reproduction, bool with_targets,
                        std::ostream& out);

}  // namespace tcsb
