// Suite: a validated benchmark description — which nets, which methods, which compression targets, how long and
// how often. Parsed from JSON by parse_suite(); everything here has already been checked.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "feedback/feedback_settings.h"
#include "harness/calibration_file.h"
#include "net/net_spec.h"
#include "softbody/solver_settings.h"
#include "softbody/tc_settings.h"

namespace tcsb {

/// The ways a case can simulate a net.
enum class Method {
  kPlain,        ///< stock btSoftBody built from the net's finest level (the baseline)
  kBulletPatch,  ///< stock btSoftBodyHelpers::CreatePatch of the same grid (checks the baseline is not handicapped)
  kTcsb,         ///< the TreeCut soft body at each compression target
};

/// Fidelity measurement settings (reference run in lockstep, error metrics).
struct FidelitySettings {
  bool enabled = false;                ///< run the full-resolution reference beside each TC-SB case
  double rms_threshold_pct = 1.0;      ///< maximal compression: smallest budget whose RMS error stays under this
  std::vector<double> pareto_targets;  ///< extra compression targets for the Pareto sweep (empty: none)
  bool ablations = false;              ///< run the equal-budget ablations
  /// The suite's calibration file as written ("converged.calibration.json", relative to the suite file); empty:
  /// none. With one, the pass adds calibrated TC-SB and the calibrated uniform grid at each target below 1.
  std::string calibration_path;
};

/// A validated suite.
/// The most repetitions a suite (or --repetitions) may ask for.
inline constexpr int kMaxRepetitions = 1000;

struct Suite {
  std::string name;
  std::string description;
  std::filesystem::path path;  ///< where it was read from
  std::string sha256;          ///< SHA-256 of the file's bytes
  std::vector<NetSpec> nets;
  std::vector<Method> methods;      ///< in the order repetitions interleave them
  std::vector<double> compression;  ///< TC-SB node budgets as fractions of the initial count; 1.0 = none
  WorldSettings world;
  int steps = 300;        ///< timed steps per repetition
  int warmup_steps = 30;  ///< untimed steps before them
  int repetitions = 5;
  std::uint64_t seed = 1;
  SolverSettings solver;
  TcSettings tcsb;
  FeedbackSettings feedback;
  FidelitySettings fidelity;
  /// The calibration fidelity.calibration_path names, read and checked against this suite (calibration_mismatch)
  /// when the suite was parsed; nullopt without one.
  std::optional<Calibration> calibration;
};

/// A suite file that cannot be used. what() is one line naming the file and the field.
class SuiteError : public std::runtime_error {
 public:
  SuiteError(const std::string& file, const std::string& field, const std::string& problem)
      : std::runtime_error(file + ": " + (field.empty() ? std::string() : field + ": ") + problem), file_(file),
        field_(field) {}
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_, field_;
};

/// Changes the command line makes to a parsed suite (--repetitions, --compression, ...); throws to reject them.
using SuiteAdjustment = std::function<void(Suite&)>;

/// Reads and validates a suite file. Throws SuiteError (unknown keys, wrong types, out-of-range values, a suite too
/// large for this process's memory limits (harness/suite_memory.h), unreadable file) before anything runs.
/// `adjust`, when given, runs on the parsed suite before the memory check, so the check sees the suite that runs.
Suite parse_suite(const std::filesystem::path& path, const SuiteAdjustment& adjust = {});

/// Validates a suite given as JSON text; `file` names it in errors. The same checks as parse_suite.
Suite parse_suite_text(const std::string& text, const std::string& file, const SuiteAdjustment& adjust = {});

/// Name used in JSON for a method ("plain", "bullet_patch", "tcsb").
const char* method_name(Method method);

}  // namespace tcsb
