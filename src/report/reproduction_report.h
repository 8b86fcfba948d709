// The reproduction report: our Tables 1 and 2 beside the paper's, and the claims checked — as a JSON section
// appended to the native report, and as text for the console.
#pragma once

#include <iosfwd>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/claim.h"
#include "harness/paper_reference.h"
#include "harness/run_result.h"

namespace tcsb {

/// A run checked against the paper.
struct Reproduction {
  PaperReference paper;
  std::vector<Claim> claims;   ///< the paper's claims (gate the exit code)
  std::vector<Claim> targets;  ///< this project's stricter targets (reported only)
  double bootstrap_s = 0;      ///< computing the claims' intervals
  double wall_s = 0;           ///< the whole reproduction: the run (fidelity pass included) and the intervals
  bool pass() const { return all_pass(claims); }
};

/// Computes the claims and targets of a finished run, with bootstrap intervals for those the repetitions measure.
Reproduction check_reproduction(const RunResult& result, PaperReference paper);

/// The `reproduction` section: side-by-side tables (paper, ours), claims, targets, pass, wall time.
nlohmann::ordered_json reproduction_json(const RunResult& result, const Reproduction& reproduction);

/// Both tables side by side with the paper's, then every claim and target with its verdict.
void print_reproduction(const RunResult& result, const Reproduction& reproduction, std::ostream& out);

}  // namespace tcsb
