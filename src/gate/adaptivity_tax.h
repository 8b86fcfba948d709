// The tax of adaptivity judged on finished runs (`tcsb tax`): per net, what a TC-SB step costs against a static
// plain body of its node budget (plain_equal) in the same repetition, pooled over one or more runs of one suite and
// build, with a staged bootstrap interval (runs, then the processes within a merged run, then their repetitions) and a
// verdict that says when the noise leaves the bound open. Pure: ResultViews in, claims out; no Bullet.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/claim.h"
#include "result/result_view.h"

namespace tcsb {

/// Fewer paired ratios than this on a net and resampling them says nothing about the noise: no interval, so the
/// net's verdict is undecided (the same floor as the reproduction's intervals).
inline constexpr std::size_t kMinTaxRatios = 5;

/// What is judged, by default this project's scaling target: TC-SB at 30 % costs at most 1.15 x plain_equal on
/// every net of 66 049 nodes (257 x 257) and more.
struct TaxTarget {
  double bound = 1.15;                 ///< the largest ratio to plain_equal that passes, > 0
  double compression = 0.3;            ///< the TC-SB cases judged: those at this node budget (a fraction in (0, 1))
  std::int64_t min_net_nodes = 66049;  ///< only nets of at least this many grid nodes (smaller ones are dominated
                                       ///< by fixed costs, and the target is stated from here on)
  /// Judge the nets together instead, as Table 2 does: one claim on the mean over the nets of TC-SB's median step
  /// over the mean of plain_equal's (each case's median over its repetitions, pooled over the runs).
  bool over_nets = false;
  double confidence = 0.95;  ///< of the bootstrap interval
  int resamples = 4000;      ///< bootstrap resamples
  std::uint64_t seed = 1;    ///< of the bootstrap: the same files give the same verdict
};

/// One net's judgement.
struct NetTax {
  std::string net;
  std::string configuration;   ///< the case's configuration label in a run with axes, else ""
  std::int64_t net_nodes = 0;  ///< grid nodes of the net
  std::size_t runs = 0;        ///< runs with at least one paired ratio on this net
  std::size_t ratios = 0;      ///< paired ratios pooled over those runs
  /// Processes the interval pooled: a run's own one, or a merged result's shards (each resampled before its ratios).
  std::size_t processes = 0;
  std::vector<double> run_medians;  ///< each run's median ratio, in the order the runs were given (one per run counted)
  /// id "tax_" + net (+ "_" + configuration), measured: the median of the pooled ratios (over one run, the case's
  /// ratio_vs_equal_plain); repeated, judged on its interval. Not measured (so failed) when a repetition of TC-SB
  /// or of plain_equal diverged: a body that blows up meets no cost target.
  Claim claim;
  std::string note;  ///< why the verdict is what it is, when it is not plain from the numbers ("" otherwise)
};

/// Judges every TC-SB case at `target.compression` that has a plain_equal case, on nets of at least
/// `target.min_net_nodes`, pooled over `runs` (matched by configuration and net). Throws SuiteMismatch when the runs
/// are of different suites, settings (repetitions aside) or seeds, or of different builds (context.git_commit), and
/// InputError (naming the file and the field) when a judged TC-SB case lacks net_nodes. Returns no nets when
/// nothing matched; the caller decides what that means. With `target.over_nets`, one entry for all the matched nets
/// together: `net` lists them ("n45+n55+..."), `net_nodes` is the smallest one's, its claim's id "tax_over_nets"
/// (+ "_" + configuration), its ratios the paired repetitions of all nets, and `run_medians` each run's own Table 2
/// ratio.
std::vector<NetTax> judge_tax(const std::vector<ResultView>& runs, const TaxTarget& target);

/// The verdict over the nets: overall_verdict() of their claims.
Verdict tax_verdict(const std::vector<NetTax>& nets);

}  // namespace tcsb
