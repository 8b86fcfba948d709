// `tcsb calibrate SUITE`: fits the resolution-consistent link stiffness of the suite (per LOD level for TC-SB, per
// budget for the uniform grid; fidelity/calibration.h) and writes the calibration file a suite refers to from its
// fidelity block. The suite is read without its current calibration (that is what is being made). With --check FILE
// it fits nothing: it measures FILE's calibration on the suite's nets in the suite's regime (whether a calibration
// transfers to other nets or another gravity) and prints each fit's error beside the error it was fitted to.
#include <CLI/CLI.hpp>
#include <iostream>
#include <sstream>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "base/terminal_text.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/run_support.h"
#include "fidelity/calibration.h"
#include "suite/calibration_path.h"

namespace tcsb::cli {

CLI::App* add_calibrate_command(CLI::App& app, CalibrateArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Fit the per-level link stiffness (and the uniform grid's) against full-resolution Bullet");
  cmd->add_option("suite", args.suite, "Suite file, or a bundled suite name")->required();
  cmd->add_option("--out", args.out,
                  "Calibration file to write (atomically); default: the suite's fidelity.calibration, else "
                  "SUITE.calibration.json beside the suite");
  cmd->add_option("--check", args.check,
                  "Fit nothing: measure this calibration file on the suite's nets and regime (does it transfer?)");
  cmd->add_flag("--quiet", args.quiet, "Print nothing but errors");
  return cmd;
}

namespace {

std::string fixed3(double v) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(3);
  s << v;
  return s.str();
}

/// --check: one line per fit, its error on these nets against the error it was fitted to.
int check_calibration(const CalibrateArgs& args, const Suite& suite,
                      const std::vector<std::shared_ptr<const Net>>& nets) {
  if (!args.out.empty()) throw UsageError("--out: --check writes nothing");
  const Calibration c = parse_calibration_file(args.check);
  if (c.piterations != suite.solver.piterations || c.linear_stiffness != suite.solver.linear_stiffness)
    throw UsageError("--check: " + args.check + " was fitted at other solver iterations or another material");
  const std::vector<StiffnessFit> measured = evaluate_calibration(c, suite, nets);
  for (const StiffnessFit& m : measured) {
    const StiffnessFit* fitted = nullptr;
    for (const StiffnessFit& f : m.level > 0 ? c.levels : c.uniform_grid)
      if (f.level == m.level && f.compression == m.compression) fitted = &f;
    const std::string what =
        m.level > 0 ? "level " + std::to_string(m.level) : "uniform grid at " + fixed3(100 * m.compression) + " %";
    if (!args.quiet)
      std::cout << terminal_safe(what + ": kLST " + fixed3(m.linear_stiffness) + ", RMS " + fixed3(m.rms_pct) +
                                 " % here (uncalibrated " + fixed3(m.uncalibrated_rms_pct) + " %), fitted " +
                                 fixed3(fitted->rms_pct) + " %: " + fixed3(m.rms_pct / fitted->rms_pct) + "x")
                << std::endl;
  }
  return kExitOk;
}

}  // namespace

int calibrate_command(const CalibrateArgs& args) {
  const std::filesystem::path suite_file = resolve_suite(args.suite);
  check_out_is_not_input(args.out, suite_file);
  check_out_is_not_input(args.out, args.check);
  std::string named;  // the suite's own calibration path, before it is cleared
  const Suite suite = parse_suite(suite_file, [&](Suite& s) {
    named = s.fidelity.calibration_path;
    s.fidelity.calibration_path.clear();  // not read: it is what this command makes (and may be stale or missing)
  });
  refuse_axes(suite, "calibrate");
  // The compliant material is one material at every level by construction: nothing to fit, and a fit would make it
  // two.
  if (suite.solver.compliant_model())
    throw InputError(suite_file.string(), "material.model",
                     "\"compliant\" suites are not calibrated: the material is what the suite says at every level");
  // A calibration without level fits is refused where it is used: do not fit and write one.
  if (calibration_levels_needed(suite) == 0)
    throw InputError(suite_file.string(), "nets",
                     "a net's first LOD level is under 5 x 5 nodes (a net under 9 x 9): no level to calibrate");
  std::vector<std::shared_ptr<const Net>> nets;
  for (const NetSpec& spec : suite.nets) nets.push_back(std::make_shared<const Net>(spec));
  if (!args.check.empty()) return check_calibration(args, suite, nets);
  std::filesystem::path out = args.out;
  if (out.empty())
    out = named.empty() ? suite_file.parent_path() / (suite_file.stem().string() + ".calibration.json")
                        : calibration_file_path(suite_file, named);  // never outside the suite's tree
  if (const std::string why = output_problem(out); !why.empty()) throw UsageError("--out: " + why);
  check_out_is_not_input(out.string(), suite_file);
  const Calibration c = calibrate_suite(suite, nets, {}, [&](const std::string& line) {
    if (!args.quiet) std::cout << terminal_safe(line) << std::endl;
  });
  write_file_atomically(out, calibration_json_text(c));
  if (!args.quiet) std::cout << "wrote " << terminal_safe(out.string()) << std::endl;
  return kExitOk;
}

}  // namespace tcsb::cli
