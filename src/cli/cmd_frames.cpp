// `tcsb frames`: the paper's Figure 6 as data — plain Bullet and TC-SB of one net in lockstep, both recorded at a
// few steps (positions, the TC-SB surface reconstructed at full resolution, TC-SB's links with their blend roles);
// of a scene of many bodies, the world pass's TC-SB and discrete LOD with every grid point's LOD level (the fly-by).
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
#include "report/world_frames_json.h"
#include "run/context.h"
#include "run/out_of_memory.h"
#include "suite/scene_bodies.h"
#include "suite/suite_memory.h"
#include "world/world_frames.h"

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

/// The steps to record: --steps, or with --every K the steps 0, K, 2K, ... up to the suite's warm-up and measured
/// steps.
std::vector<int> steps_of(const FramesArgs& args, const Suite& suite) {
  if (!args.every) return args.steps;
  if (*args.every < 1) throw UsageError("--every: give a step count of at least 1, got " + std::to_string(*args.every));
  std::vector<int> steps;
  for (int s = 0; s <= suite.warmup_steps + suite.steps; s += *args.every) steps.push_back(s);
  return steps;
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

/// The same per grid point of one method's scene in a world frame: its point and level (28 bytes), their JSON tree
/// (four values of 16 bytes) and text (about 25), with room to spare.
constexpr double kWorldFrameBytesPerPoint = 250.0;

/// What the frames will hold: `frames` frames of `points` points (`points_are` says of what) at `bytes_per_point`.
struct FramesSize {
  std::size_t frames = 0;
  std::size_t points = 0;
  const char* points_are = "";
  double bytes_per_point = 0;
};

/// Refuses the steps before anything runs when the frames would not fit this process's memory (80 % of the smallest
/// headroom, as the suites' guard): the recording and its JSON grow with the number of frames, unbounded otherwise.
/// `what` names the recording, `flag` the option that chose the steps.
void check_frames_fit(const std::string& what, const char* flag, const FramesSize& size) {
  const std::optional<MemoryHeadroom> headroom = smallest_headroom(memory_headrooms());
  if (!headroom) return;
  const double needed = size.bytes_per_point * static_cast<double>(size.frames) * static_cast<double>(size.points);
  const double usable = 0.8 * static_cast<double>(headroom->bytes);
  if (needed <= usable) return;
  throw UsageError(what + ": " + flag + " asks for " + std::to_string(size.frames) + " frames of " +
                   std::to_string(size.points) + " " + size.points_are + ", about " + format_bytes(needed) +
                   ", but only " + format_bytes(usable) + " may be used (80% of the headroom under " +
                   headroom->source + "): it would run out of memory; record fewer steps");
}

/// `tcsb frames` of a scene of many bodies: the world pass at one budget, its TC-SB and discrete LOD recorded.
int world_frames_command(const FramesArgs& args, const Suite& suite, const std::vector<int>& steps) {
  const std::string scene = "suite " + suite.name + " is a scene of many bodies (scene.bodies)";
  if (!args.net.empty()) throw UsageError("--net: " + scene + "; its frames hold every body");
  if (args.calibrated) throw UsageError("--calibrated: " + scene + ", whose world pass has no calibrated bodies");
  double compression = 1.0;
  if (args.compression) {
    compression = checked_budget(*args.compression);
  } else {
    for (const double c : suite.compression) compression = std::min(compression, c);
  }
  if (!(compression < 1.0))
    throw UsageError("--compression: " + scene + ", whose world pass runs budgets below 1 only; give one");
  const int total = suite.warmup_steps + suite.steps;
  if (steps.back() > total)
    throw UsageError("--steps: " + scene + ", whose world pass ends after " + std::to_string(total) + " steps, got " +
                     std::to_string(steps.back()));
  const std::string what = "suite " + suite.name + ", world frames";
  std::size_t points = 0;
  for (const NetSpec& n : scene_body_nets(suite)) points += static_cast<std::size_t>(n.node_count());
  check_frames_fit(what, args.every ? "--every" : "--steps",
                   {steps.size(), points * world_frame_methods(suite).size(), "grid points", kWorldFrameBytesPerPoint});
  const Context context = gather_context();  // recorded in the file, not printed: nothing here is timed
  const WorldFrames frames = naming_out_of_memory(what, [&] { return record_world_frames(suite, compression, steps); });
  for (const WorldMethodResult& m : frames.methods)
    if (m.status != "ok")
      print_warning(m.method + " diverged at step " + std::to_string(m.diverged_step.value_or(0)) + " (" +
                    m.diverged_reason + "); the frames after it are missing");
  return write_report(json_text(world_frames_json(suite, context, frames), -1), args.out);
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
  CLI::Option* steps =
      add_list_option(*cmd, "--steps", args.steps, "Steps after which both bodies are recorded, increasing")
          ->default_str(defaults);
  cmd->add_option("--every", args.every,
                  "Instead of --steps: record after every K steps, from 0 to the end of the suite's warm-up and steps")
      ->excludes(steps);
  cmd->add_flag("--calibrated", args.calibrated,
                "TC-SB with the suite's calibration (fidelity.calibration), as the fidelity pass's tcsb_calibrated");
  cmd->add_option("--out", args.out, "Write to FILE (atomically) instead of stdout");
  return cmd;
}

int frames_command(const FramesArgs& args) {
  check_out_path(args.out);
  if (!args.every) check_steps(args.steps);  // before the suite is read: a typing error fails at once
  const std::filesystem::path suite_file = resolve_suite(args.suite);
  check_out_is_not_input(args.out, suite_file);
  const Suite suite = parse_suite(suite_file);
  check_out_is_not_suite_input(args.out, suite);
  refuse_axes(suite, "frames");
  const std::vector<int> steps = steps_of(args, suite);  // --every's are in order by construction
  if (is_world_suite(suite)) return world_frames_command(args, suite, steps);
  const std::size_t net = net_index(suite, args.net);
  const NetSpec& spec = suite.nets[net];
  check_frames_fit("suite " + suite.name + ", frames of net " + spec.name, args.every ? "--every" : "--steps",
                   {steps.size(), static_cast<std::size_t>(spec.node_count()), "nodes", kFrameBytesPerNode});
  const double compression = compression_of(suite, args.compression);
  if (args.calibrated && !suite.calibration)
    throw UsageError("--calibrated: suite " + suite.name + " names no calibration (fidelity.calibration)");
  // Recorded in the file; not printed, since nothing here is timed (the warnings are about timing).
  const Context context = gather_context();
  const FigureFrames frames =
      naming_out_of_memory("suite " + suite.name + ", frames of net " + suite.nets[net].name,
                           [&] { return record_figure_frames(suite, net, compression, steps, args.calibrated); });
  if (frames.diverged_step) {
    print_warning("net " + frames.net + " diverged after step " + std::to_string(*frames.diverged_step) + " (" +
                  frames.diverged_reason + "); the frames after it are missing");
  }
  // On one line: about 200 000 numbers for an 81 x 81 net, which indented would be as many lines.
  return write_report(json_text(frames_json(suite, context, frames), -1), args.out);
}

}  // namespace tcsb::cli
