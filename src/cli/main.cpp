// tcsb: benchmark and reproduction harness for "Perception-influenced Animation". Only dispatch lives here; each
// subcommand is in its own cmd_*.cpp.
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/flag_values.h"
#include "cli/standard_streams.h"
#include "softbody/bullet_allocator.h"

namespace {

using namespace tcsb::cli;

int dispatch(int argc, char** argv) {
  CLI::App app{"tcsb: plain Bullet soft bodies vs the TreeCut soft body (TC-SB). Without a subcommand, runs the "
               "default reproduction.",
               "tcsb"};
  bool version = false;
  app.add_flag("--version", version, "Print the version, commit and Bullet version, then exit");
  ReproduceArgs reproduce_args;  // the bare `tcsb` is `tcsb reproduce`: --targets works on either
  app.add_flag("--targets", reproduce_args.targets,
               std::string("Without a subcommand, as reproduce --targets: ") + kTargetsFlagHelp);
  app.require_subcommand(0, 1);
  RunArgs run_args;
  ValidateArgs validate_args;
  CompareArgs compare_args;
  ExportArgs export_args;
  FramesArgs frames_args;
  MergeArgs merge_args;
  CalibrateArgs calibrate_args;
  TaxArgs tax_args;
  CLI::App* run = add_run_command(app, run_args);
  CLI::App* list = add_list_command(app);
  CLI::App* validate = add_validate_command(app, validate_args);
  CLI::App* reproduce = add_reproduce_command(app, reproduce_args);
  CLI::App* compare = add_compare_command(app, compare_args);
  CLI::App* export_ = add_export_command(app, export_args);
  CLI::App* frames = add_frames_command(app, frames_args);
  CLI::App* merge = add_merge_command(app, merge_args);
  CLI::App* calibrate = add_calibrate_command(app, calibrate_args);
  CLI::App* tax = add_tax_command(app, tax_args);
  reject_empty_values(app);  // after every option exists: "--out ''" must not mean stdout, nor '' mean 0

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return parse_error_exit(app, e);
  }
  return guarded([&] {
    if (version) {
      std::cout << version_line() << std::endl;
      return static_cast<int>(kExitOk);
    }
    if (*run) return run_command(run_args);
    (void)reproduce;
    if (*list) return list_command();
    if (*validate) return validate_command(validate_args);
    if (*compare) return compare_command(compare_args);
    if (*export_) return export_command(export_args);
    if (*frames) return frames_command(frames_args);
    if (*merge) return merge_command(merge_args);
    if (*calibrate) return calibrate_command(calibrate_args);
    if (*tax) return tax_command(tax_args);
    // `reproduce`, or no subcommand at all: the default job.
    return reproduce_command(reproduce_args);
  });
}

}  // namespace

int main(int argc, char** argv) {
  tcsb::install_throwing_bullet_allocator();  // before any Bullet object: a failed allocation must not be a SIGSEGV
  prepare_standard_streams();
  // Every command's output, --help and --version included, is checked here: a full disk or a closed pipe is exit 3.
  return finish_stdout(dispatch(argc, argv));
}
