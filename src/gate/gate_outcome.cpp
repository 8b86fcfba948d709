#include "gate/gate_outcome.h"

#include <algorithm>

namespace tcsb {
namespace {

std::vector<TimingSamples> samples_of(const std::vector<TimingSeries>& series) {
  std::vector<TimingSamples> out;
  out.reserve(series.size());
  for (const TimingSeries& s : series) out.push_back(s.samples);
  return out;
}

std::size_t count(const std::vector<TimingDecision>& decisions, TimingVerdict verdict) {
  std::size_t n = 0;
  for (const TimingDecision& d : decisions) n += d.verdict == verdict;
  return n;
}

std::size_t reliable(const std::vector<TimingDecision>& decisions) {
  return decisions.size() - count(decisions, TimingVerdict::kUnreliable);
}

/// Calls `fn` with every gated timing decision: the ratios, and the step times when --absolute gates them too.
template <class Fn>
void for_each_gated(const GateOutcome& o, Fn fn) {
  for (const TimingDecision& d : o.ratio_decisions) fn(d);
  if (o.absolute_gated)
    for (const TimingDecision& d : o.step_decisions) fn(d);
}

}  // namespace

std::size_t GateOutcome::unreliable_metrics() const {
  std::size_t n = 0;
  for_each_gated(*this, [&n](const TimingDecision& d) { n += d.verdict == TimingVerdict::kUnreliable; });
  return n;
}

Verdict GateOutcome::verdict() const {
  if (behaviour_changed() || regressions > 0) return Verdict::kFail;
  if (undecided > 0) return Verdict::kUndecided;
  return pass() ? Verdict::kPass : Verdict::kFail;
}

int GateOutcome::more_repetitions() const {
  int most = 0;
  for_each_gated(*this, [&most](const TimingDecision& d) {
    if (d.verdict == TimingVerdict::kUndecided) most = std::max(most, d.more_repetitions.value_or(kMaxMoreRepetitions));
  });
  return most;
}

std::pair<std::size_t, std::size_t> GateOutcome::processes() const {
  std::pair<std::size_t, std::size_t> most{1, 1};
  for_each_gated(*this, [&most](const TimingDecision& d) {
    most.first = std::max(most.first, d.base_processes);
    most.second = std::max(most.second, d.next_processes);
  });
  return most;
}

GateOutcome decide_gate(ResultComparison comparison, const GateSettings& settings, bool absolute_gated) {
  GateOutcome out;
  out.settings = settings;
  out.absolute_gated = absolute_gated;
  if (comparison.measure == "instructions") {
    out.counts = true;
    for (const InstructionPair& p : comparison.instructions) {
      out.instruction_decisions.push_back(decide_instructions(p.case_label, p.base, p.next, settings.threshold));
      out.regressions += out.instruction_decisions.back().regressed;
    }
    out.gated_metrics = out.instruction_decisions.size();
    out.comparison = std::move(comparison);
    return out;
  }
  const std::vector<TimingSamples> ratios = samples_of(comparison.ratios);
  const std::vector<TimingSamples> steps = samples_of(comparison.step_ms);
  if (absolute_gated) {
    // One family: Holm must see every metric that can fail the gate, or the false-alarm rate exceeds alpha.
    std::vector<TimingSamples> family = ratios;
    family.insert(family.end(), steps.begin(), steps.end());
    std::vector<TimingDecision> all = decide_timings(family, settings);
    out.ratio_decisions.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(ratios.size()));
    out.step_decisions.assign(all.begin() + static_cast<std::ptrdiff_t>(ratios.size()), all.end());
    out.gated_metrics = reliable(all);
    out.regressions = count(all, TimingVerdict::kRegressed);
    out.undecided = count(all, TimingVerdict::kUndecided);
  } else {
    out.ratio_decisions = decide_timings(ratios, settings);
    out.step_decisions = decide_timings(steps, settings);
    out.gated_metrics = reliable(out.ratio_decisions);
    out.regressions = count(out.ratio_decisions, TimingVerdict::kRegressed);
    out.undecided = count(out.ratio_decisions, TimingVerdict::kUndecided);
    out.warnings = count(out.step_decisions, TimingVerdict::kRegressed);
  }
  out.comparison = std::move(comparison);
  return out;
}

}  // namespace tcsb
