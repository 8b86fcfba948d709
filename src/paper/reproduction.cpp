#include "paper/reproduction.h"

#include <utility>

#include "case/step_clock.h"
#include "paper/claim_scope.h"
#include "paper/op_work_claims.h"
#include "paper/paper_claims.h"
#include "run/runner.h"

namespace tcsb {
namespace {

/// The deterministic targets: judged on their values, once, after the looks.
TrackedClaim untracked(Claim c) {
  TrackedClaim t;
  t.claim = std::move(c);
  t.gates = false;
  return t;
}

}  // namespace

ReproductionTables reproduction_tables(const RunResult& result) {
  ReproductionTables t;
  t.run = run_tables(result);
  t.plain_fit = step_fit_of_method(result, Method::kPlain);
  t.tcsb_fit = step_fit_of_method(result, Method::kTcsb);
  return t;
}

Verdict Reproduction::verdict() const {
  std::vector<Claim> all;
  for (const TrackedClaim& t : claims) all.push_back(t.claim);
  return overall_verdict(all);
}

Reproduction check_reproduction(RunResult& result, PaperReference paper, const ReproductionOptions& options) {
  Reproduction r;
  r.paper = std::move(paper);
  r.budget_s = options.budget_s;
  const PaperReference& ref = r.paper;
  SequentialHooks hooks;
  hooks.claims_of = [&ref](const RunResult& run) {
    const std::vector<Table2Row> rows = table2(run);  // once for both lists: this runs for every resample
    return JudgedClaims{paper_claims(ref, rows, step_fit_of_method(run, Method::kTcsb), table1(run)),
                        project_targets(rows)};
  };
  hooks.scope_of = scope_of;
  hooks.run_more =
      options.run_more ? options.run_more : [](RunResult& run, const std::vector<std::size_t>& cases, int extra) {
        run_more_repetitions(run, cases, extra);
      };
  const StepClock::time_point start = StepClock::now();
  hooks.now_s = [start] { return ms_between(start, StepClock::now()) / 1000.0; };
  hooks.on_look = options.on_look;
  SequentialSettings settings;
  settings.budget_s = options.budget_s;
  settings.seed = result.suite.seed;  // the same measurements give the same intervals
  SequentialOutcome outcome = judge_sequentially(result, settings, hooks);

  r.claims = std::move(outcome.claims);
  // Figure 4 (operations constant in time) is judged on deterministic work counts, not on wall time, which this
  // machine's memory hierarchy decides (docs/methodology.md, "The memory floor"): decided on their values.
  for (Claim& c : op_work_claims(result)) {
    TrackedClaim t;  // a claim of the paper: it gates like the others
    t.claim = std::move(c);
    r.claims.push_back(std::move(t));
  }
  for (const TrackedClaim& t : r.claims) {
    if (t.claim.id != kNoCompressionClaimId) continue;
    TrackedClaim sanity = t;  // the claim's look, repetitions and confidence: it reads the same interval
    sanity.claim = nocompression_sanity(t.claim);
    sanity.gates = false;
    r.sanity.push_back(std::move(sanity));
  }
  r.targets = std::move(outcome.targets);
  r.looks = std::move(outcome.looks);
  r.ended = outcome.ended;
  r.bootstrap_s = outcome.bootstrap_s;
  r.wall_s = result.wall_s + r.bootstrap_s;  // result.wall_s includes the extra repetitions
  r.targets.push_back(untracked(wall_time_target(r.wall_s)));
  r.tables = reproduction_tables(result);
  if (r.tables.run.fidelity) {  // reported beside the speed targets; like them, they do not gate the exit code
    for (const Claim& c : r.tables.run.fidelity->targets) r.targets.push_back(untracked(c));
  }
  return r;
}

}  // namespace tcsb
