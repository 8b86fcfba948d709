// Calibration file: the per-level link stiffness that makes a coarse TC-SB cut behave like the fine net (and the
// stiffness that does the same for the uniform grid of each budget), as `tcsb calibrate SUITE` fitted it, with the
// settings it was fitted under and the error each value reached. A suite refers to one from its fidelity block
// ("calibration": a path relative to the suite file); parsing the suite checks that the file was fitted for the
// suite's nets, material, iteration count, dt, gravity and steps (calibration_key()), so a calibration is never
// applied to a regime it was not fitted in.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "net/net_spec.h"

namespace tcsb {

struct Suite;

/// One fitted stiffness.
struct StiffnessFit {
  int level = 0;                    ///< LOD level (level fits); 0 for a uniform-grid fit
  double compression = 1.0;         ///< the budget (uniform-grid fits); 1 for level fits
  double linear_stiffness = 1.0;    ///< the fitted kLST, in (0, 1]
  double rms_pct = 0;               ///< mean over the suite's nets of the mean-over-steps RMS it reached
  double uncalibrated_rms_pct = 0;  ///< the same at the solver's stiffness (what the fit improved on)
  int evaluations = 0;              ///< simulations of the suite's nets the search ran
};

/// A whole calibration.
struct Calibration {
  std::string suite;                       ///< name of the suite it was fitted on
  std::string key;                         ///< calibration_key() of that suite
  int piterations = 0;                     ///< the solver's iterations it was fitted at
  double linear_stiffness = 1.0;           ///< the solver's material (level 0, the reference's)
  std::vector<StiffnessFit> levels;        ///< level 1, 2, ... in order
  std::vector<StiffnessFit> uniform_grid;  ///< per compression target below 1, ascending
  /// TcSettings::level_stiffness: the levels' fitted values in order.
  std::vector<double> level_stiffness() const;
  /// The uniform grid's fitted stiffness at a budget, if fitted.
  std::optional<double> uniform_stiffness(double compression) const;
};

/// The most LOD levels `tcsb calibrate` fits (CalibrationSearch::max_levels, fidelity/calibration.h): the levels
/// above take the last fitted value.
inline constexpr int kMaxCalibratedLevels = 3;

/// The LOD levels a calibration fits on these nets: 1 .. max_levels, stopping before a level whose grid is under
/// 5 x 5 on any net. From the nets' sizes alone (level l of the LOD tree is ceil(size / 2^l) wide and high,
/// net/lod_tree.cpp), so the suite can be checked before any net is built.
int calibrated_level_count(const std::vector<NetSpec>& nets, int max_levels);

/// The levels a calibration of `suite` must fit: calibrated_level_count of its nets, up to kMaxCalibratedLevels.
int calibration_levels_needed(const Suite& suite);

/// SHA-256 over what the fit depends on: every net's geometry, mass and pins, dt, gravity, steps, warm-up, the
/// solver settings and, in a scene with colliders, the colliders and contact settings. Not the suite's name,
/// description, methods, repetitions, feedback or fidelity block: a suite that differs only there can share the
/// calibration.
std::string calibration_key(const Suite& suite);

/// The calibration as the file's JSON text (pretty, one trailing newline).
std::string calibration_json_text(const Calibration& calibration);

/// Reads a calibration file. Throws InputError("FILE: FIELD: problem") on a bad file.
Calibration parse_calibration_file(const std::filesystem::path& path);

/// Empty when `calibration` was fitted for `suite`'s regime and fits every level its nets need
/// (calibration_levels_needed; none at all, "levels": [], never: the calibrated TC-SB would run uncalibrated under
/// that name); else why not (one phrase naming what differs).
std::string calibration_mismatch(const Calibration& calibration, const Suite& suite);

}  // namespace tcsb
