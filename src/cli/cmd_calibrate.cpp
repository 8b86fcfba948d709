// `tcsb calibrate SUITE`: fits the resolution-consistent link stiffness of the suite (per LOD level for TC-SB, per
// budget for the uniform grid; fidelity/calibration.h) and writes the calibration file a suite refers to from its
// fidelity block. The suite is read without its current calibration (that is what is being made).
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "fidelity/calibration.h"
#include "report/report_writer.h"
#include "report/terminal_text.h"

namespace tcsb::cli {

CLI::App* add_calibrate_command(CLI::App& app, CalibrateArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Fit the per-level link stiffness (and the uniform grid's) against full-resolution Bullet");
  cmd->add_option("suite", args.suite, "Suite file, or a bundled suite name")->required();
  cmd->add_option("--out", args.out,
                  "Calibration file to write (atomically); default: the suite's fidelity.calibration, else "
                  "SUITE.calibration.json beside the suite");
  cmd->add_flag("--quiet", args.quiet, "Print nothing but errors");
  return cmd;
}

int calibrate_command(const CalibrateArgs& args) {
  const std::filesystem::path suite_file = resolve_suite(args.suite);
  std::string named;  // the suite's own calibration path, before it is cleared
  const Suite suite = parse_suite(suite_file, [&](Suite& s) {
    named = s.fidelity.calibration_path;
    s.fidelity.calibration_path.clear();  // not read: it is what this command makes (and may be stale or missing)
  });
  refuse_axes(suite, "calibrate");
  std::filesystem::path out = args.out;
  if (out.empty())
    out = named.empty() ? suite_file.parent_path() / (suite_file.stem().string() + ".calibration.json")
                        : suite_file.parent_path() / named;
  if (const std::string why = output_problem(out); !why.empty()) throw UsageError("--out: " + why);
  std::vector<std::shared_ptr<const Net>> nets;
  for (const NetSpec& spec : suite.nets) nets.push_back(std::make_shared<const Net>(spec));
  const Calibration c = calibrate_suite(suite, nets, {}, [&](const std::string& line) {
    if (!args.quiet) std::cout << terminal_safe(line) << std::endl;
  });
  write_file_atomically(out, calibration_json_text(c));
  if (!args.quiet) std::cout << "wrote " << terminal_safe(out.string()) << std::endl;
  return kExitOk;
}

}  // namespace tcsb::cli
