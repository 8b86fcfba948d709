// FidelityResult: what the fidelity pass measured — per net and subject, error against the full-resolution
// reference summarised over the measured steps, energy drift, popping, and the subject's own step time beside the
// reference's, both timed in the same pass.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/statistics.h"
#include "suite/fidelity_plan.h"

namespace tcsb {

/// A per-step metric summarised over the measured steps.
struct MetricSummary {
  std::size_t count = 0;  ///< steps summarised (0: never measured; the numbers are then meaningless)
  double mean = 0;
  double p95 = 0;
  double max = 0;
};

/// The count, mean, p95 and maximum of a per-step series (0 steps: all 0).
inline MetricSummary summarize_metric(std::span<const double> values) {
  const Summary s = summarize(values);
  return {s.count, s.mean, s.p95, s.max};
}

/// A summary's mean, or nothing when it summarised no step (a subject that never reached a measured step).
inline std::optional<double> summary_mean(const MetricSummary& s) {
  return s.count > 0 ? std::optional(s.mean) : std::nullopt;
}

/// Error as the spectator sees it, in a scene with a camera (fidelity/screen_error.h): per measured step the mean,
/// p95 and maximum distance on the image, pixels, between the reference's and the subject's grid points that the
/// reference shows in view; each summarised over the steps that show any.
struct ScreenMetrics {
  MetricSummary mean_px;
  MetricSummary p95_px;
  MetricSummary max_px;
  double p95_over_1px_share = 0;  ///< share of those steps whose p95 exceeds one pixel
  double points_in_view = 0;      ///< grid points in view, mean over the measured steps
};

/// One subject on one net.
struct FidelityCase {
  std::size_t net = 0;  ///< index into Suite::nets
  std::string net_name;
  FidelitySubjectSpec subject;
  int target_nodes = 0;              ///< the node budget (compression x grid nodes)
  double mean_nodes = 0;             ///< simulated (Bullet) nodes, mean over measured steps
  std::string grid;                  ///< the coarse grid ("44x44") for uniform_grid and switch_body; else empty
  std::string status = "ok";         ///< "ok" or "diverged" (the subject's or the reference's; then no metrics)
  std::optional<int> diverged_step;  ///< step (counting warm-up) at which it diverged
  std::string diverged_reason;
  // Metrics, each per step in percent: of the net's extent (Net::extent()) for distances, of the reference's
  // initial energy (M g h, y from 0) for the drift. Summarised over the measured steps, popping over all steps.
  MetricSummary rms_pct;                ///< RMS distance of the reconstructed grid nodes from the reference's
  MetricSummary max_pct;                ///< largest distance of any grid node
  MetricSummary weighted_rms_pct;       ///< RMS weighted by the reference's saliency at that step
  MetricSummary popping_pct;            ///< largest jump of any reconstructed node across a step boundary's operations
                                        ///< (0 where none happened); over every step, warm-up included
  MetricSummary energy_drift_pct;       ///< 100 |E - E_ref| / |E_ref(0)| (energy_drift_pct())
  std::optional<ScreenMetrics> screen;  ///< in a scene with a camera
  double step_ms = 0;                   ///< mean wall time of the subject's own steps (blends, feedback, operations,
                                        ///< switch, Bullet) over the measured steps, run on its own
  double reference_step_ms = 0;         ///< mean wall time of the reference's steps in the same pass (recording run)
  /// Mean step wall time of each block of measured steps (the pass interleaves bodies in blocks), in pass order:
  /// the units an interval of a time ratio resamples. Empty for a diverged subject and in results written before.
  std::vector<double> block_step_ms;
  std::optional<double> switch_ms;    ///< switch_body: building the coarse body, moving the state, freeing the fine
  std::optional<int> switch_step;     ///< switch_body: the step at whose boundary it switched
  std::optional<int> converged_step;  ///< TC-SB under a budget: the step at whose boundary it first fitted it
  std::string final_state_hash;       ///< state_hash of the subject's body at the end (TC-SB: equals the timed
                                      ///< case's hash at the same target: the pass measured the timed trajectory)
};

/// The interpolation floor of one budget on one net (fidelity/fidelity_floors.h).
struct InterpolationFloor {
  double compression = 1.0;  ///< the budget, as a fraction of the net's nodes
  std::string grid;          ///< the uniform rest grid of the budget's node count ("70x70")
  MetricSummary rms_pct;     ///< RMS of the reference's surface resampled through that grid, per measured step
};

/// One doubling tried: the full-resolution body at `substeps` against itself at twice as many, and against itself
/// started perturbed (the noise floor, fidelity_floors.h), mean over the measured steps of the RMS, % of the extent.
struct SubstepDoubling {
  int substeps = 0;
  double change_rms_pct = 0;  ///< `substeps` against 2 x `substeps`
  double noise_rms_pct = 0;   ///< `substeps` against itself perturbed
  bool diverged = false;      ///< one of the three bodies diverged: the doubling says nothing
};

/// How the reference's small steps were chosen.
struct ReferenceSubsteps {
  int substeps = 0;                        ///< what the reference steps with
  bool converged = false;                  ///< doubling it moved the surface less than the noise floor
  std::vector<SubstepDoubling> doublings;  ///< every doubling tried, in order
};

/// What no subject on a net can be expected to beat (fidelity/fidelity_floors.h), in % of the net's extent, per
/// measured step; count 0 where the reference diverged first.
struct FidelityFloors {
  std::size_t net = 0;  ///< index into Suite::nets
  std::string net_name;
  MetricSummary noise_rms_pct;  ///< RMS of the reference started perturbed (kNoiseFloorPerturbation) against itself
  std::optional<ScreenMetrics> noise_screen;      ///< the same perturbed reference's screen error, with a camera
  std::vector<InterpolationFloor> interpolation;  ///< one per distinct budget of the plan, ascending
  /// Under the compliant material: how the converged reference's small steps were found (converged_reference.h).
  std::optional<ReferenceSubsteps> reference;
  /// The reference's mean step wall time per block of measured steps, as FidelityCase::block_step_ms.
  std::vector<double> reference_block_step_ms;
};

/// The whole fidelity pass of a run.
struct FidelityResult {
  double rms_threshold_pct = 1.0;      ///< the suite's threshold for the maximal compression
  std::vector<FidelityCase> cases;     ///< per net (suite order), subjects in fidelity_plan() order
  std::vector<FidelityFloors> floors;  ///< per net (suite order)
  double wall_s = 0;                   ///< wall time of the pass (included in the run's wall_s)
};

}  // namespace tcsb
