#include "paper/sequential_claims.h"

#include "analysis/bootstrap.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "paper/claim_intervals.h"

namespace tcsb {

namespace {

/// Predicted repetition costs are multiplied by this: the machine's speed drifts between looks.
constexpr double kCostMargin = 1.25;

std::vector<TrackedClaim> tracked(const std::vector<Claim>& claims, bool gates, const SequentialHooks& hooks) {
  std::vector<TrackedClaim> out;
  for (const Claim& c : claims) {
    TrackedClaim& t = out.emplace_back();
    t.claim = c;
    t.gates = gates;
    if (c.evidence == Evidence::kRepeated) t.scope = hooks.scope_of(c.id);
  }
  return out;
}

std::vector<Claim> all_claims(const RunResult& result, const SequentialHooks& hooks) {
  JudgedClaims judged = hooks.claims_of(result);
  judged.claims.insert(judged.claims.end(), judged.targets.begin(), judged.targets.end());
  return std::move(judged.claims);
}

/// The fewest and the most repetitions among `cases`.
std::pair<int, int> repetitions_of(const RunResult& result, const std::vector<std::size_t>& cases) {
  int fewest = 0, most = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const int n = static_cast<int>(result.cases[cases[k]].repetitions.size());
    fewest = k == 0 ? n : std::min(fewest, n);
    most = std::max(most, n);
  }
  return {fewest, most};
}

/// How many processes measured the repetitions of `cases` (one in a run of one process; a merged result's shards).
std::size_t processes_of(const RunResult& result, const std::vector<std::size_t>& cases) {
  std::vector<int> process_of;
  for (const std::size_t i : cases)
    for (const RepetitionResult& r : result.cases[i].repetitions) process_of.push_back(r.process);
  return process_count(process_of);
}

/// Judges `judged` (pointers into the outcome) at look `look`: fresh values on the whole run, intervals from a
/// bootstrap of just the cases they read. Returns the look's record (without its extra repetitions and seconds).
Look judge(RunResult& result, const std::vector<TrackedClaim*>& judged, int look, const SequentialSettings& settings,
           const SequentialHooks& hooks) {
  Look record;
  record.look = look;
  record.confidence = look_confidence(settings.alpha, look);
  record.resamples = look_resamples(settings.alpha, look);
  record.judged = static_cast<int>(judged.size());
  if (judged.empty()) return record;
  ClaimScope scope;
  for (const TrackedClaim* t : judged) scope = merged(scope, *t->scope);
  const std::vector<std::size_t> cases = cases_in_scope(result, scope);
  record.repetitions = repetitions_of(result, cases).second;

  std::map<std::string, Claim> fresh;
  for (const Claim& c : all_claims(result, hooks)) fresh.emplace(c.id, c);
  const RunResult subset = subset_for_bootstrap(result, cases, scope.operations);
  const ClaimReplicates replicates = bootstrap_claims(
      subset, [&](const RunResult& r) { return all_claims(r, hooks); }, record.resamples,
      settings.seed + static_cast<std::uint64_t>(look - 1));
  for (TrackedClaim* t : judged) {
    if (const auto it = fresh.find(t->claim.id); it != fresh.end()) t->claim.measured = it->second.measured;
    std::vector<Claim> one{t->claim};
    attach_intervals(one, replicates, record.confidence);
    t->claim.interval = one.front().interval;
    t->look = look;
    t->confidence = record.confidence;
    const std::vector<std::size_t> own = cases_in_scope(result, *t->scope);
    t->repetitions = repetitions_of(result, own).first;
    t->processes = processes_of(result, own);
  }
  return record;
}

}  // namespace

double repetition_cost_s(const RunResult& result, const std::vector<std::size_t>& cases) {
  const double steps = static_cast<double>(steps_per_repetition(result.suite));
  double total_ms = 0;
  for (const std::size_t i : cases) {
    const CaseResult& c = result.cases[i];
    if (c.repetitions.empty()) continue;
    double sum = 0;
    for (const RepetitionResult& r : c.repetitions) sum += r.build_ms + steps * r.mean_step_ms;
    total_ms += sum / static_cast<double>(c.repetitions.size());
  }
  return total_ms / 1000.0;
}

SequentialOutcome judge_sequentially(RunResult& result, const SequentialSettings& settings,
                                     const SequentialHooks& hooks) {
  SequentialOutcome out;
  const JudgedClaims judged = hooks.claims_of(result);
  out.claims = tracked(judged.claims, true, hooks);
  out.targets = tracked(judged.targets, false, hooks);

  // What is still followed: judged on an interval, at every look so far, and undecided at the last.
  std::vector<TrackedClaim*> following;
  for (std::vector<TrackedClaim>* list : {&out.claims, &out.targets})
    for (TrackedClaim& t : *list)
      if (t.scope) following.push_back(&t);
  const auto timed_judge = [&](const std::vector<TrackedClaim*>& judged, int look) {
    const double t0 = hooks.now_s();
    Look record = judge(result, judged, look, settings, hooks);
    const double seconds = hooks.now_s() - t0;
    out.bootstrap_s += seconds;
    return std::pair(record, seconds);
  };
  const auto undecided_claims = [&] {
    int n = 0;
    for (const TrackedClaim& t : out.claims) n += verdict(t.claim) == Verdict::kUndecided ? 1 : 0;
    return n;
  };

  const double start = hooks.now_s();  // the budget counts from here: the first look's intervals are part of it
  auto [first, first_bootstrap_s] = timed_judge(following, 1);
  first.undecided = undecided_claims();
  first.seconds = first_bootstrap_s;
  out.looks.push_back(first);
  if (hooks.on_look) hooks.on_look(first);
  // Seconds per (resample x case repetition) of the last bootstrap: predicts the next one's cost.
  double bootstrap_unit_s = 0;
  if (first.resamples > 0 && first.repetitions > 0)
    bootstrap_unit_s = first_bootstrap_s / (first.resamples * static_cast<double>(first.repetitions));

  for (int look = 2;; ++look) {
    // Follow on only what is undecided; extra repetitions only for the paper's claims (targets ride along).
    std::erase_if(following, [](const TrackedClaim* t) { return verdict(t->claim) != Verdict::kUndecided; });
    ClaimScope pending;
    bool any_claim = false;
    for (const TrackedClaim* t : following) {
      if (!t->gates) continue;
      pending = merged(pending, *t->scope);
      any_claim = true;
    }
    if (!any_claim) {
      out.ended = LooksEnded::kDecided;
      break;
    }
    if (look > settings.max_looks) {
      out.ended = LooksEnded::kMaxLooks;
      break;
    }
    const std::vector<std::size_t> ran = cases_in_scope(result, pending);
    const int have = repetitions_of(result, ran).first;
    // Double the repetitions (reaching at least enough for an interval); at least half of that, or not at all.
    const int floor_for_intervals = static_cast<int>(kMinRepetitionsForIntervals) - have;
    const int desired = std::max(have, floor_for_intervals);
    const int least = std::max((desired + 1) / 2, floor_for_intervals);
    const double per_repetition_s = kCostMargin * repetition_cost_s(result, ran);
    const double bootstrap_s = bootstrap_unit_s * look_resamples(settings.alpha, look) * (have + desired);
    const double left_s = settings.budget_s - (hooks.now_s() - start) - kCostMargin * bootstrap_s;
    int extra = desired;
    if (per_repetition_s > 0) extra = std::min(desired, static_cast<int>(std::floor(left_s / per_repetition_s)));
    if (left_s <= 0 || extra < std::max(1, least)) {
      out.ended = LooksEnded::kBudget;
      break;
    }

    const double t0 = hooks.now_s();
    hooks.run_more(result, ran, extra);
    // Judged again: what is followed and whose cases all ran (a target whose cases did not is left as it was).
    std::erase_if(following, [&](const TrackedClaim* t) { return !all_among(cases_in_scope(result, *t->scope), ran); });
    auto [record, judge_s] = timed_judge(following, look);
    record.extra = extra;
    record.cases = ran.size();
    record.undecided = undecided_claims();
    record.seconds = hooks.now_s() - t0;
    if (record.resamples > 0 && record.repetitions > 0)
      bootstrap_unit_s = judge_s / (record.resamples * static_cast<double>(record.repetitions));
    out.looks.push_back(record);
    if (hooks.on_look) hooks.on_look(record);
  }
  return out;
}

const char* looks_ended_name(LooksEnded ended) {
  switch (ended) {
    case LooksEnded::kDecided: return "decided";
    case LooksEnded::kBudget: return "budget";
    case LooksEnded::kMaxLooks: return "max_looks";
  }
  return "unknown";
}

}  // namespace tcsb
