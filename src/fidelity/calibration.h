// The calibration `tcsb calibrate` runs: per LOD level, the link stiffness with which a TC-SB body whose whole cut is
// at that level (TC-SB's own masses and links, the body the fidelity pass simulates) follows the full-resolution
// plain reference most closely; per compression target, the same for the uniform grid of the budget's node count
// (the fair rival). Each is a one-dimensional search (analysis/line_search.h): no closed formula exists for how
// Bullet's Gauss-Seidel link relaxation stiffens with fewer, longer links.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "net/net.h"
#include "softbody/tc_softbody.h"
#include "suite/calibration_file.h"
#include "suite/suite.h"

namespace tcsb {

/// Called with one line per finished fit.
using CalibrationProgress = std::function<void(const std::string& line)>;

/// The search's settings.
struct CalibrationSearch {
  double lo = 0.02;                       ///< smallest kLST tried
  double hi = 1.0;                        ///< largest (the solver's usual material)
  int scan_points = 7;                    ///< uniform scan before the golden section
  double tolerance = 0.01;                ///< final bracket width in kLST
  int max_levels = kMaxCalibratedLevels;  ///< fit levels 1 .. this (fewer when a net's level grid gets under 5 x 5)
};

/// Fits `suite` (its nets, built as `nets`, same order): the levels, then the uniform grid at each compression target
/// below 1. Deterministic.
Calibration calibrate_suite(const Suite& suite, const std::vector<std::shared_ptr<const Net>>& nets,
                            const CalibrationSearch& search = {}, const CalibrationProgress& progress = {});

/// How `calibration` does on `suite`'s nets (built as `nets`, same order) in `suite`'s regime, which need not be the
/// one it was fitted in: whether a calibration transfers to other nets or another gravity. One fit per fit of the
/// calibration: each level's (a TC-SB cut at that level with the calibration's level stiffness), and each uniform
/// grid's whose budget is one of the suite's compression targets; each with the calibration's stiffness and
/// rms_pct measured here (mean over the nets, as calibrate_suite measures it; uncalibrated_rms_pct with every link at
/// the solver's stiffness). Levels the nets are too small for (calibrated_level_count()) are left out.
/// Deterministic.
std::vector<StiffnessFit> evaluate_calibration(const Calibration& calibration, const Suite& suite,
                                               const std::vector<std::shared_ptr<const Net>>& nets);

/// calibrated_level_count (suite/calibration_file.h) of the built nets' specs.
int calibrated_level_count(const std::vector<std::shared_ptr<const Net>>& nets, int max_levels);

}  // namespace tcsb
