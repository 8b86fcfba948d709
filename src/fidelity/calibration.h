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
  double lo = 0.02;         ///< smallest kLST tried
  double hi = 1.0;          ///< largest (the solver's usual material)
  int scan_points = 7;      ///< uniform scan before the golden section
  double tolerance = 0.01;  ///< final bracket width in kLST
  int max_levels = 3;       ///< fit levels 1 .. this (fewer when a net's level grid gets under 5 x 5)
};

/// Fits `suite` (its nets, built as `nets`, same order): the levels, then the uniform grid at each compression target
/// below 1. Deterministic.
Calibration calibrate_suite(const Suite& suite, const std::vector<std::shared_ptr<const Net>>& nets,
                            const CalibrationSearch& search = {}, const CalibrationProgress& progress = {});

/// Coarsens `body` (at rest, before its first step) until every block that can be is at `level`: level by level,
/// rounds of begin_coarse on every node can_coarsen allows, each round's blends run to their end. Returns the
/// committed node count.
int coarsen_to_level(TcSoftBody& body, int level);

/// The levels the calibration fits on these nets: 1 .. max_levels, stopping before a level whose grid is under
/// 5 x 5 on any net.
int calibrated_level_count(const std::vector<std::shared_ptr<const Net>>& nets, int max_levels);

}  // namespace tcsb
