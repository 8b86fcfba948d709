// `tcsb frames`: the paper's Figure 6 as data — plain Bullet and TC-SB of one net in lockstep, both recorded at a
// few steps (positions, the TC-SB surface reconstructed at full resolution, TC-SB's links with their blend roles).
// scripts/render-figures.py draws it. Nothing is timed.
#include <CLI/CLI.hpp>
#include <algorithm>

#include "base/memory_limits.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/flag_values.h"
#include "cli/run_support.h"
#include "fidelity/figure_frames.h"
#include "report/frames_json.h"
#include "report/json_report.h"
#include "run/context.h"
#include "run/out_of_memory.h"
#include "suite/suite_memory.h"

namespace tcsb::cli {

namespace {

/// The suite's net called `name`; the last (largest in the bundled suites) when `name` is empty.
std::size_t net_index(const Suite& suite, const std::string& name) {
  if (suite.nets.empty()) throw UsageError("--suite: the suite has no nets");
  if (name.empty()) return suite.nets.size() - 1;
  for (std::size_t i = 0; i < suite.nets.size(); ++i) {
    if (suite.nets[i].name == name) return i;
  }
  std::string known;
  for (const NetSpec& n : suite.nets) known += (known.empty() ? "" : ", ") + n.name;
  throw UsageError("--net: the suite has no net \"" + name + "\" (it has: " + known + ")");
}

/// The TC-SB node budget: --compression, else the suite's smallest target.
double compression_of(const Suite& suite, const std::optional<double>& given) {
  if (given) return checked_budget(*given);
  return suite.compression.empty() ? 1.0 : *std::min_element(suite.compression.begin(), suite.compression.end());
}

void check_steps(const std::vector<int>& steps) {
  if (steps.empty()) throw UsageError("--steps: give at least one step");
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i] < 0 || steps[i] > kMaxFrameStep)
      throw UsageError("--steps: each step must be from 0 to " + std::to_string(kMaxFrameStep) + ", got " +
                       std::to_string(steps[i]));
    if (i > 0 && steps[i] <= steps[i - 1]) throw UsageError("--steps: steps must be given in increasing order");
  }
}

/// What one frame costs per grid node, from the recording to the written text: both bodies' points and TC-SB's
/// nodes and links (about 100 bytes), their JSON tree (about 700) and text (about 250), with room to spare.
constexpr double kFrameBytesPerNode = 1200.0;

/// Refuses --steps before anything runs when the frames would not fit this process's memory (80 % of the smallest
/// headroom, as the suites' guard): the recording and its JSON grow with the number of frames, unbounded otherwise.
void check_frames_fit(const Suite& suite, std::size_t net, std::size_t frames) {
  const std::optional<MemoryHeadroom> headroom = smallest_headroom(memory_headrooms());
  if (!headroom) return;
  const NetSpec& spec = suite.nets[net];
  const double needed = kFrameBytesPerNode * static_cast<double>(frames) * static_cast<double>(spec.node_count());
  const double usable = 0.8 * static_cast<double>(headroom->bytes);
  if (needed <= usable) return;
  throw UsageError("suite " + suite.name + ", frames of net " + spec.name + ": --steps asks for " +
                   std::to_string(frames) + " frames of " + std::to_string(spec.node_count()) + " nodes, about " +
                   format_bytes(needed) + ", but only " + format_bytes(usable) + " may be used (80% of the headroom " +
                   "under " + headroom->source + "): it would run out of memory; record fewer steps");
}

}  // namespace

CLI::App* add_frames_command(CLI::App& app, FramesArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "frames", "Record plain Bullet and TC-SB side by side at a few steps (the paper's Figure 6) as JSON");
  cmd->add_option("--suite", args.suite, "Suite whose net, solver and feedback settings to use")->capture_default_str();
  cmd->add_option("--net", args.net, "Net of the suite (default: its last)");
  cmd->add_option("--compression", args.compression,
                  "TC-SB node budget as a fraction of the net's nodes (default: the suite's smallest target)");
  std::string defaults;
  for (const int step : args.steps) defaults += (defaults.empty() ? "" : ",") + std::to_string(step);
  add_list_option(*cmd, "--steps", args.steps, "Steps after which both bodies are recorded, increasing")
      ->default_str(defaults);
  cmd->add_flag("--calibrated", args.calibrated,
                "TC-SB with the suite's calibration (fidelity.calibration), as the fidelity pass's tcsb_calibrated");
  cmd->add_option("--out", args.out, "Write to FILE (atomically) instead of stdout");
  return cmd;
}

int frames_command(const FramesArgs& args) {
  check_out_path(args.out);
  check_steps(args.steps);
  const std::filesystem::path suite_file = resolve_suite(args.suite);
  check_out_is_not_input(args.out, suite_file);
  const Suite suite = parse_suite(suite_file);
  check_out_is_not_suite_input(args.out, suite);
  refuse_axes(suite, "frames");
  const std::size_t net = net_index(suite, args.net);
  check_frames_fit(suite, net, args.steps.size());
  const double compression = compression_of(suite, args.compression);
  if (args.calibrated && !suite.calibration)
    throw UsageError("--calibrated: suite " + suite.name + " names no calibration (fidelity.calibration)");
  // Recorded in the file; not printed, since nothing here is timed (the warnings are about timing).
  const Context context = gather_context();
  const FigureFrames frames =
      naming_out_of_memory("suite " + suite.name + ", frames of net " + suite.nets[net].name,
                           [&] { return record_figure_frames(suite, net, compression, args.steps, args.calibrated); });
  if (frames.diverged_step) {
    print_warning("net " + frames.net + " diverged after step " + std::to_string(*frames.diverged_step) + " (" +
                  frames.diverged_reason + "); the frames after it are missing");
  }
  // On one line: about 200 000 numbers for an 81 x 81 net, which indented would be as many lines.
  return write_report(json_text(frames_json(suite, context, frames), -1), args.out);
}

}  // namespace tcsb::cli
