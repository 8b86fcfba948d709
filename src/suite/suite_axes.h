// Suite axes: a suite may vary some of its own settings ("axes": {"solver.piterations": [2, 8, 32], ...}); the cross
// product of the values is the suite's configurations, and every case runs once per configuration. Only scalar
// settings of how one case simulates can be axes (the solver, TC-SB, feedback and world settings, seed, steps); what
// shapes the cases themselves (nets, methods, compression), how they are measured (repetitions) or what the machine
// gives them (feedback.parallel, threads, max_step_ms) stays one value per suite. Which settings may be axes is their
// row's word in suite/suite_settings_table.h, and an axis value is read by that row, so it is checked exactly like
// the setting itself.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "suite/suite.h"
#include "suite/suite_fields.h"

namespace tcsb {

/// The most configurations the axes of one suite may make (a bound against typing errors: a suite of that many
/// configurations already runs each of its cases a thousand times).
inline constexpr std::size_t kMaxConfigurations = 1000;

/// The settings that can be axes, by path, in the order their values appear in configuration labels.
std::vector<std::string> axis_setting_paths();

/// Reads the suite's "axes" object into suite.axes and expands suite.configurations. Throws InputError naming the
/// file and the field ("axes.solver.piterations[1]: must be an integer in [1, 1000], got 0") for an unknown path, a
/// setting that cannot be an axis, an empty list, a value its setting refuses, a value given twice, or more than
/// kMaxConfigurations configurations.
void parse_axes(const suite_fields::Reader& r, const nlohmann::json& axes, Suite& suite);

/// The suite one configuration runs: the base settings with the configuration's axis values applied, no axes, and
/// run_units narrowed to the configuration's units. Without axes (configuration 0), the suite itself.
Suite configuration_suite(const Suite& suite, std::size_t configuration);

/// configuration_suite() of every configuration, in order (one without axes).
std::vector<Suite> configuration_suites(const Suite& suite);

/// The axis values of a configuration as {path: value} in axis order, as the suite file spells them.
nlohmann::ordered_json configuration_values(const Suite& suite, std::size_t configuration);

}  // namespace tcsb
