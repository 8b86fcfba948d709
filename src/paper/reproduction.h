// The reproduction: the paper's claims judged in looks (paper/sequential_claims.h) on a finished run — which claim
// families gate the exit code, which are the project's targets and sanity lines, reported only — and the paper's
// tables, fits and fidelity rows of the run after its last look, computed once here so that every renderer
// (report/reproduction_report.h: JSON and console) receives them and computes nothing.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "analysis/claim.h"
#include "paper/paper_reference.h"
#include "paper/paper_tables.h"
#include "paper/run_tables.h"
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

/// The paper's tables of one state of a run, computed once, for the renderers.
struct ReproductionTables {
  RunTables run;      ///< the run's tables, which its native JSON renders too
  StepFit plain_fit;  ///< Figure 5's line of plain Bullet (reported, not claimed)
  StepFit tcsb_fit;   ///< Figure 5's line of TC-SB (all budgets)
};

/// The tables of `result` as it stands.
ReproductionTables reproduction_tables(const RunResult& result);

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
  double wall_s = 0;          ///< the whole reproduction: the run, fidelity pass, extra repetitions, intervals
  ReproductionTables tables;  ///< of the run after its last look (its extra repetitions included)
  /// Over the paper's claims: kFail if any failed, else kUndecided if any is undecided, else kPass.
  Verdict verdict() const;
};

/// Judges the paper's claims and the project's targets on a finished run, in looks: the claims its repetitions
/// cannot decide get extra repetitions of their cases (added to `result`) while the budget allows. Then computes
/// the tables of the run as the looks left it.
Reproduction check_reproduction(RunResult& result, PaperReference paper, const ReproductionOptions& options = {});

}  // namespace tcsb
