// The paper's tables and figures derived from a RunResult: Table 2 (cost per method and compression, averaged over
// the test set), Table 1 (cost of each TreeCut operation split into node and link work), and the linear fits of
// Figures 4 and 5 (step time and operation time against node count). Pure functions: no Bullet, no I/O, so every
// report format shows the same numbers and tests can feed hand-made results.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "run/run_result.h"
#include "softbody/op_sample.h"

namespace tcsb {

/// One row of Table 2: a (method, compression) group averaged over its nets.
struct Table2Row {
  std::string method;                         ///< "plain", "bullet_patch", "tcsb" or "plain_equal"
  std::optional<double> compression;          ///< TC-SB or plain_equal target; nullopt for the other methods
  std::string compression_label;              ///< "-", "NoCompression" (1.0) or a percentage such as "75%"
  std::optional<double> N, L, I;              ///< mean over the group's ok cases of mean nodes / links / interpolations
  std::optional<double> total_ms;             ///< mean over the group's ok cases of the median step time
  std::optional<double> time_ratio_vs_plain;  ///< mean ms / plain mean ms over the nets both have ok
  std::optional<double> node_ratio;           ///< N / plain N over the nets both have ok
  /// TC-SB rows: mean ms / the mean ms of plain_equal at the same target, over the nets both have ok — what TC-SB
  /// costs against a static body of (about) the node count it simulates. nullopt without plain_equal cases.
  std::optional<double> time_ratio_vs_equal_plain;
  int nets = 0;               ///< ok cases averaged (one per net)
  std::string status = "ok";  ///< "ok", "partial" (some nets diverged, left out) or "diverged" (none ok)
};

/// One row of Table 1: every sample of one operation kind, pooled over the ok TC-SB cases.
struct Table1Row {
  std::string operation;          ///< "refine", "end-refine", "coarse", "end-coarse"
  double N = 0, L = 0;            ///< mean Bullet nodes / links present when the operation ran
  double node_ops_ms = 0;         ///< mean time on nodes
  double link_ops_ms = 0;         ///< mean time on links
  double complete_ms = 0;         ///< mean of node + link time
  double node_ops_pct = 0;        ///< 100 * node / (node + link), from the means
  double link_ops_pct = 0;        ///< 100 * link / (node + link), from the means
  std::size_t count = 0;          ///< samples (0: the kind never ran; all numbers are then 0)
  double p50_us = 0, p99_us = 0;  ///< percentiles of the complete time, microseconds
};

/// One (x, y) point of a scaling fit: node count against milliseconds.
struct ScalingPoint {
  double nodes = 0;
  double ms = 0;
};

/// Step time against node count for one (method, compression) group (Figure 5), one point per net.
struct StepFit {
  std::string method;
  std::optional<double> compression;
  bool valid = false;  ///< false when the points do not define a line (then numbers are null)
  std::optional<double> slope_ms_per_node, intercept_ms, r2;
  /// Slope of log(ms) against log(nodes): 1 for a straight line through the origin, above 1 for superlinear growth.
  std::optional<double> loglog_exponent;
  std::vector<ScalingPoint> points;  ///< ascending nodes
};

/// Operation time against node count for one operation kind (Figure 4), one point per net.
struct OpFit {
  std::string operation;
  bool valid = false;
  std::optional<double> slope_ms_per_node, intercept_ms, r2;
  /// slope * (max nodes - min nodes) / median ms: how much the fitted cost changes across the sizes measured,
  /// relative to the typical cost; "flat in N" means < kFlatnessTarget.
  std::optional<double> flatness;
  std::vector<ScalingPoint> points;  ///< ascending nodes
};

/// The "constant in N" criterion for operation costs: the fitted change across the measured sizes stays under 20 %
/// of the typical cost.
inline constexpr double kFlatnessTarget = 0.2;

/// Table 2: one row per (method, compression) group in order of first appearance among the cases. Diverged cases
/// are left out, never averaged in; ratios compare only nets that are ok in both the group and plain, so a net that
/// diverged in one method cannot bias the other's ratio.
std::vector<Table2Row> table2(const RunResult& result);

/// A compression target as a whole percentage for claim ids: 0.75 -> "75".
std::string compression_percent(double compression);

/// Table 2's compression column: "-" without a target, "NoCompression" for 1.0, otherwise a percentage ("75%").
std::string compression_label(std::optional<double> compression);

/// The same-run, interleaved ratio of a case to a base case: the median over repetitions ok in both of
/// case.mean_step_ms / base.mean_step_ms (paired by repetition number). nullopt if an index is out of range or no
/// repetition pairs up.
std::optional<double> paired_ratio(const RunResult& result, std::size_t case_index, std::size_t base_case_index);

/// The plain case of the same net and configuration as `case_index` (the case itself if it is plain), or nullopt.
std::optional<std::size_t> plain_case_for(const RunResult& result, std::size_t case_index);

/// For a TC-SB case, the plain_equal case of the same net, configuration and compression (the static plain grid of
/// its node budget), or nullopt (other methods, or no plain_equal in the run).
std::optional<std::size_t> equal_plain_case_for(const RunResult& result, std::size_t case_index);

/// Table 1: rows for refine, end-refine, coarse, end-coarse (OpKind order) over all op samples of the ok TC-SB
/// cases. A case with a diverged repetition is left out: its samples cannot be told apart by repetition.
std::vector<Table1Row> table1(const RunResult& result);

/// Figure 5: per (method, compression) group with at least 2 ok cases, step time (median) against mean nodes.
std::vector<StepFit> step_ms_vs_nodes(const RunResult& result);

/// Figure 5 over the whole test set: one line through every usable case of `method` — for TC-SB every budget of
/// every net (each case one point: its mean simulated nodes, its median step time). `compression` is left empty.
/// Invalid (and without numbers) with fewer than 2 points.
StepFit step_fit_of_method(const RunResult& result, Method method);

/// Figure 4: per operation kind (always all four, OpKind order), one point per net pooled over that net's ok TC-SB
/// cases (mean nodes, median complete time), and the fit.
std::vector<OpFit> op_ms_vs_nodes(const RunResult& result);

}  // namespace tcsb
