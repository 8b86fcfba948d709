#include "paper/claim_intervals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/bootstrap.h"
#include "run/case_summary.h"

namespace tcsb {

namespace {

/// The run without what the claims never read (per-step series, fidelity pass), so resampling copies little.
RunResult without_series(const RunResult& result) {
  RunResult light;
  light.suite = result.suite;
  light.context = result.context;
  light.wall_s = result.wall_s;
  light.cases = result.cases;
  for (CaseResult& c : light.cases)
    for (RepetitionResult& r : c.repetitions) r.series = StepSeries{};
  return light;
}

/// Where each repetition's operation samples start in the case's pooled samples (one past the end last).
std::vector<std::size_t> sample_offsets(const CaseResult& c) {
  std::vector<std::size_t> offsets{0};
  for (const RepetitionResult& r : c.repetitions)
    offsets.push_back(offsets.back() + static_cast<std::size_t>(r.operations));
  if (offsets.back() != c.ops.samples.size())
    throw std::logic_error("resample_repetitions: " + c.label + ": operation samples do not match repetitions");
  return offsets;
}

}  // namespace

RunResult subset_for_bootstrap(const RunResult& result, const std::vector<std::size_t>& case_indices,
                               bool keep_operations) {
  RunResult subset;
  subset.suite = result.suite;
  subset.context = result.context;
  subset.wall_s = result.wall_s;
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    if (std::find(case_indices.begin(), case_indices.end(), i) == case_indices.end()) continue;
    CaseResult& c = subset.cases.emplace_back(result.cases[i]);
    for (RepetitionResult& r : c.repetitions) {
      r.series = StepSeries{};
      if (!keep_operations) r.operations = 0;
    }
    if (!keep_operations) c.ops.samples.clear();
  }
  return subset;
}

RunResult resample_repetitions(const RunResult& result, std::mt19937_64& rng) {
  RunResult out;
  out.suite = result.suite;
  out.context = result.context;
  out.wall_s = result.wall_s;
  out.cases.reserve(result.cases.size());
  // Drawn once per net (processes first, then repetitions within them), with the net's repetitions by process; or
  // once for every net when they ran side by side in the same processes.
  std::vector<std::vector<int>> processes;  // per case, the process of each repetition
  for (const CaseResult& c : result.cases) {
    std::vector<int>& process_of = processes.emplace_back();
    for (const RepetitionResult& r : c.repetitions) process_of.push_back(r.process);
  }
  const bool draw_together = result.suite.interleave_across_nets && !processes.empty() &&
                             std::all_of(processes.begin(), processes.end(),
                                         [&](const std::vector<int>& p) { return p == processes.front(); });
  std::map<std::size_t, std::pair<std::vector<int>, std::vector<std::size_t>>> picks_of_net;
  for (std::size_t ci = 0; ci < result.cases.size(); ++ci) {
    const CaseResult& c = result.cases[ci];
    const std::vector<int>& process_of = processes[ci];
    auto [it, first] = picks_of_net.try_emplace(draw_together ? 0 : c.key.net);
    if (first) it->second = {process_of, resample_grouped(process_of, rng)};
    const std::vector<std::size_t>& picks = it->second.second;
    // Side by side, every case of a net ran its repetition r in the same process.
    if (process_of != it->second.first)
      throw std::logic_error("resample_repetitions: the cases of " + c.net_name + " differ in repetitions");
    const std::vector<std::size_t> offsets = sample_offsets(c);

    CaseResult& r = out.cases.emplace_back();
    r.key = c.key;
    r.label = c.label;
    r.net_name = c.net_name;
    r.net_nodes = c.net_nodes;
    r.net_links = c.net_links;
    r.target_nodes = c.target_nodes;
    for (std::size_t i = 0; i < picks.size(); ++i) {
      RepetitionResult& rep = r.repetitions.emplace_back(c.repetitions[picks[i]]);
      rep.series = StepSeries{};
      rep.repetition = static_cast<int>(i);
      const auto first = c.ops.samples.begin() + static_cast<std::ptrdiff_t>(offsets[picks[i]]);
      const auto last = c.ops.samples.begin() + static_cast<std::ptrdiff_t>(offsets[picks[i] + 1]);
      r.ops.samples.insert(r.ops.samples.end(), first, last);
    }
    summarize_case(r);
  }
  return out;
}

ClaimReplicates bootstrap_claims(const RunResult& result,
                                 const std::function<std::vector<Claim>(const RunResult&)>& claims_of, int resamples,
                                 std::uint64_t seed) {
  ClaimReplicates replicates;
  for (const CaseResult& c : result.cases)
    if (c.repetitions.size() < kMinRepetitionsForIntervals) return replicates;
  const RunResult light = without_series(result);
  std::mt19937_64 rng(seed);
  for (int i = 0; i < resamples; ++i) {
    for (const Claim& claim : claims_of(resample_repetitions(light, rng)))
      replicates[claim.id].push_back(claim.measured ? *claim.measured : std::numeric_limits<double>::quiet_NaN());
  }
  return replicates;
}

void attach_intervals(std::vector<Claim>& claims, const ClaimReplicates& replicates, double confidence) {
  for (Claim& claim : claims) {
    const auto it = replicates.find(claim.id);
    claim.interval = it == replicates.end() ? std::nullopt : percentile_interval(it->second, confidence);
  }
}

}  // namespace tcsb
