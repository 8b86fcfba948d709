#include "gate/adaptivity_tax.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "analysis/bootstrap.h"
#include "analysis/statistics.h"
#include "gate/result_comparison.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// Runs pooled into one verdict must have measured the same thing with the same code: the same suite and settings
/// (each may have run its own number of repetitions) and seed, and the same build.
void check_poolable(const std::vector<ResultView>& runs) {
  const auto commit = [](const ResultView& r) { return r.context.value("git_commit", ojson()); };
  for (std::size_t i = 1; i < runs.size(); ++i) {
    std::string difference = suite_difference(runs.front(), runs[i], true);
    if (difference.empty() && commit(runs.front()) != commit(runs[i]))
      difference = "context.git_commit: " + commit(runs.front()).dump() + " vs " + commit(runs[i]).dump();
    if (!difference.empty())
      throw SuiteMismatch(runs.front().file + " and " + runs[i].file +
                          " cannot be pooled: they are runs of different suites, settings or builds (" + difference +
                          ")");
  }
}

/// The first repetition of `c` that did not end ok, as "METHOD diverged at step S in FILE, repetition R"; "" if none.
std::string first_failure(const ResultView& run, const CaseView& c) {
  for (const RepetitionView& r : c.repetitions) {
    if (r.status == "ok") continue;
    std::string where = c.method + " " + r.status;
    if (r.diverged_step) where += " at step " + std::to_string(*r.diverged_step);
    return where + " in " + run.file + ", repetition " + std::to_string(r.repetition);
  }
  return "";
}

/// A number as a reader writes it: 0.3 -> "0.3", 1.15 -> "1.15" (at most six significant digits).
std::string text(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

/// The pooled ratios of one net, one group per run.
struct NetSamples {
  NetTax tax;
  std::vector<std::vector<double>> per_run;
  std::string failure;  ///< the first repetition that did not end ok, "" if none
};

void judge(NetSamples& s, const TaxTarget& target) {
  NetTax& t = s.tax;
  std::vector<double> pooled;
  for (const std::vector<double>& run : s.per_run) {
    if (run.empty()) continue;
    ++t.runs;
    t.run_medians.push_back(median(run));
    pooled.insert(pooled.end(), run.begin(), run.end());
  }
  t.ratios = pooled.size();
  std::optional<double> measured;
  if (s.failure.empty() && !pooled.empty()) measured = median(pooled);
  std::string id = "tax_" + t.net + (t.configuration.empty() ? "" : "_" + t.configuration);
  std::string description = "TC-SB at " + text(target.compression * 100.0) + "% on " + t.net + " costs at most " +
                            text(target.bound) + " x plain_equal (the same repetition)";
  t.claim = check_claim(std::move(id), std::move(description), Comparison::kAtMost, target.bound, 0.0, measured,
                        Evidence::kRepeated);
  if (!s.failure.empty()) {
    t.note = "not measured: " + s.failure;
    return;
  }
  if (pooled.size() < kMinTaxRatios) {
    t.note = std::to_string(pooled.size()) + " paired ratio(s), fewer than " + std::to_string(kMinTaxRatios) +
             ": no interval, so undecided (add repetitions or runs)";
    return;
  }
  // Seeded by the net, so its interval does not depend on which other nets were judged.
  std::mt19937_64 rng(target.seed * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(t.net_nodes));
  std::vector<double> replicates;
  replicates.reserve(static_cast<std::size_t>(target.resamples));
  for (int i = 0; i < target.resamples; ++i) replicates.push_back(median(resample_groups(s.per_run, rng)));
  t.claim.interval = percentile_interval(std::move(replicates), target.confidence);
}

}  // namespace

std::vector<NetTax> judge_tax(const std::vector<ResultView>& runs, const TaxTarget& target) {
  check_poolable(runs);
  std::vector<NetSamples> nets;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const ResultView& run = runs[r];
    for (std::size_t i = 0; i < run.cases.size(); ++i) {
      const CaseView& c = run.cases[i];
      if (c.method != "tcsb" || !c.compression || std::abs(*c.compression - target.compression) > 1e-9) continue;
      const std::optional<std::size_t> equal = equal_plain_case_of(run, i);
      if (!equal) continue;
      if (!c.net_nodes)
        throw ResultFileError(run.file, "cases[" + std::to_string(i) + "].net_nodes",
                              "missing (needed to tell whether the net is judged)");
      if (*c.net_nodes < target.min_net_nodes) continue;
      auto it = std::find_if(nets.begin(), nets.end(), [&](const NetSamples& s) {
        return s.tax.net == c.net && s.tax.configuration == c.configuration;
      });
      if (it == nets.end()) {
        NetSamples fresh;
        fresh.tax.net = c.net;
        fresh.tax.configuration = c.configuration;
        fresh.tax.net_nodes = *c.net_nodes;
        fresh.per_run.resize(runs.size());
        nets.push_back(std::move(fresh));
        it = std::prev(nets.end());
      }
      if (it->failure.empty()) it->failure = first_failure(run, c);
      if (it->failure.empty()) it->failure = first_failure(run, run.cases[*equal]);
      it->per_run[r] = paired_step_ratios(run, i, *equal);
    }
  }
  std::vector<NetTax> out;
  for (NetSamples& s : nets) {
    judge(s, target);
    out.push_back(std::move(s.tax));
  }
  return out;
}

Verdict tax_verdict(const std::vector<NetTax>& nets) {
  std::vector<Claim> claims;
  for (const NetTax& n : nets) claims.push_back(n.claim);
  return overall_verdict(claims);
}

}  // namespace tcsb
