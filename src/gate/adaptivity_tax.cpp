#include "gate/adaptivity_tax.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <sstream>

#include "analysis/bootstrap.h"
#include "analysis/relative_change.h"
#include "analysis/statistics.h"
#include "base/case_pairing.h"
#include "gate/result_comparison.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// Runs pooled into one verdict must have measured the same thing with the same code: the same suite and settings
/// (each may have run its own number of repetitions) and seed, and the same build (commit, compiler, flags, build
/// type, sanitizers, Bullet's precision: a Debug or double-precision run is another population, not more noise).
void check_poolable(const std::vector<ResultView>& runs) {
  for (std::size_t i = 1; i < runs.size(); ++i) {
    std::string difference = suite_difference(runs.front(), runs[i], true);
    if (difference.empty()) difference = build_difference(runs.front(), runs[i]);
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

/// A net's repetitions in one run: TC-SB's mean step (case_ms) and plain_equal's (base_ms), paired by number.
using Pairs = std::vector<PairedStepTimes>;

/// Table 2's ratio: the mean over the nets of TC-SB's median time over the mean of plain_equal's. NaN when a net has
/// no pair (a resample cannot leave one empty, the data can).
double ratio_of_means(const std::vector<Pairs>& per_net) {
  double tcsb = 0.0, equal = 0.0;
  for (const Pairs& pairs : per_net) {
    if (pairs.empty()) return std::nan("");
    std::vector<double> t, e;
    for (const PairedStepTimes& p : pairs) {
      t.push_back(p.case_ms);
      e.push_back(p.base_ms);
    }
    tcsb += median(t);
    equal += median(e);
  }
  return tcsb / equal;
}

/// The pooled pairs of one net, one group per run.
struct NetSamples {
  NetTax tax;
  std::vector<Pairs> per_run;
  std::string failure;  ///< the first repetition that did not end ok, "" if none
};

/// The claim's measured value, note and interval, the same for a net and for the nets together: not measured when a
/// repetition failed; undecided without an interval below kMinTaxRatios samples (`fewest`, counted in `unit`);
/// else the percentile interval of `target.resamples` values of `replicate`, drawn from a generator seeded with `seed`.
void finish_claim(NetTax& t, const std::string& failure, std::size_t fewest, const char* unit, const TaxTarget& target,
                  std::uint64_t seed, const std::function<double(std::mt19937_64&)>& replicate) {
  if (!failure.empty()) {
    t.note = "not measured: " + failure;
    return;
  }
  if (fewest < kMinTaxRatios) {
    t.note = std::to_string(fewest) + " " + unit + ", fewer than " + std::to_string(kMinTaxRatios) +
             ": no interval, so undecided (add repetitions or runs)";
    return;
  }
  std::mt19937_64 rng(seed);
  std::vector<double> replicates;
  replicates.reserve(static_cast<std::size_t>(target.resamples));
  for (int i = 0; i < target.resamples; ++i) replicates.push_back(replicate(rng));
  t.claim.interval = percentile_interval(std::move(replicates), target.confidence);
}

/// The processes of a net's pairs in one run.
std::vector<int> processes_of(const Pairs& pairs) {
  std::vector<int> process_of;
  for (const PairedStepTimes& p : pairs) process_of.push_back(p.process);
  return process_of;
}

void judge(NetSamples& s, const TaxTarget& target) {
  NetTax& t = s.tax;
  std::vector<double> pooled;
  // Only the runs that have this net are resampled: a run without it (a shard of other nets) has no ratio to give,
  // and drawing it would add an empty group, whose median reads as a ratio of 0.
  std::vector<std::vector<double>> per_run;
  std::vector<std::vector<int>> process_of;  // per run, each ratio's process
  for (const Pairs& pairs : s.per_run) {
    std::vector<double> run;
    std::vector<int> processes;
    for (const PairedStepTimes& p : pairs) {
      if (const auto q = safe_ratio(p.case_ms, p.base_ms)) {
        run.push_back(*q);
        processes.push_back(p.process);
      }
    }
    if (run.empty()) continue;
    per_run.push_back(run);
    t.processes += process_count(processes);
    process_of.push_back(std::move(processes));
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
  // Seeded by the net, so its interval does not depend on which other nets were judged.
  finish_claim(t, s.failure, pooled.size(), "paired ratio(s)", target,
               target.seed * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(t.net_nodes),
               [&](std::mt19937_64& rng) {
                 // Runs first, then in each drawn run its processes (a merged result's shards), then their ratios.
                 std::vector<double> drawn;
                 for (const std::size_t r : resample_indices(per_run.size(), rng))
                   for (const std::size_t k : resample_grouped(process_of[r], rng)) drawn.push_back(per_run[r][k]);
                 return median(drawn);
               });
}

/// The nets of one configuration judged together (Table 2's ratio), pooled over the runs: the runs are drawn again
/// once for all nets (a run measured every net in one process), then, per net, each drawn run's repetitions.
NetTax judge_over_nets(const std::vector<NetSamples>& nets, const TaxTarget& target) {
  NetTax t;
  t.configuration = nets.front().tax.configuration;
  t.net_nodes = nets.front().tax.net_nodes;
  std::string failure;
  for (const NetSamples& n : nets) {
    t.net += (t.net.empty() ? "" : "+") + n.tax.net;
    t.net_nodes = std::min(t.net_nodes, n.tax.net_nodes);
    if (failure.empty()) failure = n.failure;
  }
  const std::size_t run_count = nets.front().per_run.size();
  std::vector<Pairs> pooled(nets.size());
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  for (std::size_t r = 0; r < run_count; ++r) {
    std::vector<Pairs> of_run;
    for (std::size_t n = 0; n < nets.size(); ++n) {
      of_run.push_back(nets[n].per_run[r]);
      pooled[n].insert(pooled[n].end(), nets[n].per_run[r].begin(), nets[n].per_run[r].end());
    }
    const double ratio = ratio_of_means(of_run);
    if (std::isnan(ratio)) continue;  // a run without these nets (a shard of others)
    ++t.runs;
    t.run_medians.push_back(ratio);
  }
  for (const Pairs& p : pooled) {
    t.ratios += p.size();
    fewest = std::min(fewest, p.size());
  }
  for (std::size_t r = 0; r < run_count; ++r) {
    std::vector<int> processes;
    for (const NetSamples& n : nets)
      for (const int p : processes_of(n.per_run[r])) processes.push_back(p);
    t.processes += process_count(processes);
  }
  std::optional<double> measured;
  if (failure.empty() && fewest > 0) measured = ratio_of_means(pooled);
  t.claim =
      check_claim("tax_over_nets" + (t.configuration.empty() ? "" : "_" + t.configuration),
                  "TC-SB at " + text(target.compression * 100.0) + "% over the nets " + t.net + " costs at most " +
                      text(target.bound) + " x plain_equal (Table 2's ratio of the nets' mean steps)",
                  Comparison::kAtMost, target.bound, 0.0, measured, Evidence::kRepeated);
  finish_claim(t, failure, fewest, "repetition(s) on a net", target, target.seed * 0x9E3779B97F4A7C15ull,
               [&](std::mt19937_64& rng) {
                 const std::vector<std::size_t> drawn_runs = resample_indices(run_count, rng);
                 std::vector<Pairs> drawn(nets.size());
                 for (std::size_t n = 0; n < nets.size(); ++n) {
                   for (const std::size_t r : drawn_runs) {
                     const Pairs& pairs = nets[n].per_run[r];
                     for (const std::size_t k : resample_grouped(processes_of(pairs), rng))
                       drawn[n].push_back(pairs[k]);
                   }
                 }
                 return ratio_of_means(drawn);  // NaN (dropped) when the drawn runs miss a net
               });
  return t;
}

}  // namespace

std::vector<NetTax> judge_tax(const std::vector<ResultView>& runs, const TaxTarget& target) {
  check_poolable(runs);
  std::vector<NetSamples> nets;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const ResultView& run = runs[r];
    for (std::size_t i = 0; i < run.cases.size(); ++i) {
      const CaseView& c = run.cases[i];
      if (c.method != "tcsb" || !c.compression || !same_compression(*c.compression, target.compression)) continue;
      const std::optional<std::size_t> equal = equal_plain_case_of(run, i);
      if (!equal) continue;
      if (!c.net_nodes)
        throw InputError(run.file, "cases[" + std::to_string(i) + "].net_nodes",
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
      it->per_run[r] = paired_step_times(run, i, *equal);
    }
  }
  std::vector<NetTax> out;
  if (target.over_nets) {
    // One claim per configuration, its nets in the order the runs list them.
    std::vector<std::string> configurations;
    for (const NetSamples& s : nets)
      if (std::find(configurations.begin(), configurations.end(), s.tax.configuration) == configurations.end())
        configurations.push_back(s.tax.configuration);
    for (const std::string& configuration : configurations) {
      std::vector<NetSamples> of_configuration;
      for (const NetSamples& s : nets)
        if (s.tax.configuration == configuration) of_configuration.push_back(s);
      out.push_back(judge_over_nets(of_configuration, target));
    }
    return out;
  }
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
