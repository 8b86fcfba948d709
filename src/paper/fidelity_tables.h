// The fidelity tables derived from a FidelityResult: one row per (method, compression) averaged over the nets, the
// time-versus-error Pareto sweep of TC-SB, the maximal compression factor, and the fidelity targets. Pure functions:
// no Bullet, no I/O, so every report shows the same numbers and tests can feed hand-made results.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/claim.h"
#include "fidelity/fidelity_result.h"
#include "paper/equal_error_table.h"

namespace tcsb {

/// One (method, compression) group of the fidelity pass over its ok nets. Metric summaries combine the nets' as:
/// mean and p95 = mean over nets of each net's value, max = max over nets (so "every step of every net").
struct FidelityRow {
  std::string method;  ///< FidelitySubjectSpec::method
  double compression = 1.0;
  int solver_divisor = 1;   ///< full_resolution: what the suite's passes a step were divided by
  std::optional<double> N;  ///< simulated nodes, mean over nets of the per-net mean
  MetricSummary rms_pct, max_pct, weighted_rms_pct, popping_pct, energy_drift_pct;  ///< count = nets combined
  std::optional<double> worst_net_rms_pct;  ///< the largest per-net rms_pct.mean (the maximal compression uses it)
  /// Mean over nets of the subject's mean step ms / mean over nets of the reference's, both timed in the pass.
  std::optional<double> time_ratio_vs_plain;
  std::optional<double> switch_ms;  ///< switch_body: mean over nets
  /// Mean over the row's ok nets of each net's noise floor (FidelityFloors::noise_rms_pct mean); nullopt when a
  /// net has none (a result without floors, or a perturbed reference that diverged).
  std::optional<double> noise_floor_pct;
  /// Mean over the row's ok nets of each net's interpolation floor at the row's budget (its uniform rest grid).
  std::optional<double> interpolation_floor_pct;
  std::string grid;           ///< uniform/switch: the coarse grids, e.g. "25x25..44x44"
  int nets = 0;               ///< ok nets combined
  std::string status = "ok";  ///< "ok", "partial" (some nets diverged, left out), "diverged" (none ok)
};

/// Rows in order of first appearance among the cases (fidelity_plan order). Diverged cases are left out.
std::vector<FidelityRow> fidelity_rows(const FidelityResult& result);

/// One compression target of TC-SB in the time-versus-error sweep.
struct ParetoPoint {
  double compression = 1.0;
  std::optional<double> N;
  std::optional<double> time_ratio_vs_plain;
  std::optional<double> rms_pct;            ///< the row's rms_pct.mean: mean over nets of the mean over steps
  std::optional<double> worst_net_rms_pct;  ///< the largest per-net mean-over-steps RMS
  /// No other point is at least as fast and at least as accurate and strictly better in one of them.
  bool on_front = false;
};

/// The rows of `method` (TC-SB by default; "tcsb_calibrated" for the calibrated body's sweep) as a sweep, ascending
/// compression; points without a ratio or an error are never on the front.
std::vector<ParetoPoint> pareto_sweep(const std::vector<FidelityRow>& rows, const std::string& method = "tcsb");

/// The maximal compression factor: the smallest budget (fraction of the net's nodes) such that it and every larger
/// target of the sweep keep the worst net's mean-over-steps RMS error at most `threshold_pct` of the net's extent.
/// Requiring every larger target too keeps one lucky target below a failing one from being reported. The same rule on
/// the mean over the nets is reported beside it (mean_compression).
struct MaxCompression {
  double threshold_pct = 1.0;
  std::optional<double> compression;          ///< nullopt: no target qualifies
  std::optional<double> rms_pct;              ///< the worst net's RMS at that target
  std::optional<double> time_ratio_vs_plain;  ///< the speed it buys
  /// The same rule on the mean over the nets (each net's mean-over-steps RMS, averaged), the convention of the
  /// other fidelity targets: a budget and every larger one keep the mean within the threshold. Where both exist it
  /// is at most `compression`, since the mean never exceeds the worst net.
  std::optional<double> mean_compression;
  std::optional<double> mean_rms_pct;              ///< the mean RMS at that target
  std::optional<double> mean_time_ratio_vs_plain;  ///< the speed it buys
};
MaxCompression max_compression(const std::vector<ParetoPoint>& sweep, double threshold_pct);

/// The fidelity targets (reported, not gating): TC-SB RMS at most 1 % of the net's extent at 75 % and 2 % at 30 %;
/// saliency-weighted RMS of TC-SB at most half the uniform coarse grid's at each ablated target; popping at most
/// 0.5 % of the extent for every operation (TC-SB at every target below 1). With a calibration's rows, also the
/// converged regime's: calibrated TC-SB RMS at most 0.5 % at 75 % and 1 % at 30 %, and its saliency-weighted RMS at
/// most 0.7 x the calibrated uniform grid's. A target with no measurement fails.
std::vector<Claim> fidelity_targets(const std::vector<FidelityRow>& rows);

/// A fidelity pass as every report shows it, computed once: the rows, TC-SB's sweep and maximal compression (and
/// calibrated TC-SB's, with a calibration), and the targets.
struct FidelityTables {
  std::vector<FidelityRow> rows;
  std::vector<ParetoPoint> sweep;             ///< TC-SB's
  MaxCompression max_compression;             ///< over `sweep`, at the pass's threshold
  std::vector<ParetoPoint> calibrated_sweep;  ///< calibrated TC-SB's; empty without a calibration
  MaxCompression calibrated_max_compression;  ///< over `calibrated_sweep` (meaningful only when it is not empty)
  std::vector<Claim> targets;
  std::vector<EqualErrorNet> equal_error;  ///< the speed-up at equal error; empty without fidelity.curves
};

/// The fidelity tables of a pass, its maximal compressions at the pass's rms_threshold_pct.
FidelityTables fidelity_tables(const FidelityResult& result);

}  // namespace tcsb
