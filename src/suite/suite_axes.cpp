#include "suite/suite_axes.h"

#include <climits>
#include <stdexcept>
#include <string_view>

namespace tcsb {
namespace {

using namespace suite_fields;

/// Reads one value of a setting into a suite, checking it as the suite file's own field is checked.
using SettingReader = void (*)(const Reader& r, const json& value, const std::string& at, Suite& s);

struct AxisSetting {
  std::string_view path;
  SettingReader read;
};

int whole(const Reader& r, const json& v, const std::string& at, long long lo, long long hi) {
  return static_cast<int>(r.integer(v, at, lo, hi));
}

// The axis-able settings, in label order. Every one is a single number, flag or choice that only changes how a case
// simulates, so configurations of one suite run the same cases and their ratios, tables and fits compare.
const AxisSetting kAxisSettings[] = {
    {"solver.piterations", [](const Reader& r, const json& v, const std::string& at,
                              Suite& s) { s.solver.piterations = whole(r, v, at, 1, 1000); }},
    {"solver.viterations", [](const Reader& r, const json& v, const std::string& at,
                              Suite& s) { s.solver.viterations = whole(r, v, at, 0, 1000); }},
    {"solver.diterations", [](const Reader& r, const json& v, const std::string& at,
                              Suite& s) { s.solver.diterations = whole(r, v, at, 0, 1000); }},
    {"solver.damping",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) {
       s.solver.damping = r.number(v, at, NumberRange{0.0, false, 1.0, true});
     }},
    {"solver.stiffness", [](const Reader& r, const json& v, const std::string& at,
                            Suite& s) { s.solver.linear_stiffness = r.number(v, at, kFraction); }},
    {"tcsb.blend_steps", [](const Reader& r, const json& v, const std::string& at,
                            Suite& s) { s.tcsb.blend_steps = whole(r, v, at, 1, 1000); }},
    {"tcsb.start_level", [](const Reader& r, const json& v, const std::string& at,
                            Suite& s) { s.tcsb.start_level = whole(r, v, at, 0, 30); }},
    {"tcsb.placement",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) {
       s.tcsb.placement = r.choice<Placement>(v, at, {{"affine", Placement::kAffine}, {"rigid", Placement::kRigid}});
     }},
    {"tcsb.interfaces",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) {
       s.tcsb.interfaces =
           r.choice<Interfaces>(v, at, {{"links", Interfaces::kLinks}, {"hanging", Interfaces::kHanging}});
     }},
    {"tcsb.restore_order",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) { s.tcsb.restore_order = r.boolean(v, at); }},
    {"tcsb.exact_order",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) { s.tcsb.exact_order = r.boolean(v, at); }},
    {"tcsb.restore_order_min_nodes", [](const Reader& r, const json& v, const std::string& at,
                                        Suite& s) { s.tcsb.restore_order_min_nodes = whole(r, v, at, 0, INT_MAX); }},
    {"tcsb.rebuild_dbvt",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) { s.tcsb.rebuild_dbvt = r.boolean(v, at); }},
    {"tcsb.arrivals_collide", [](const Reader& r, const json& v, const std::string& at,
                                 Suite& s) { s.tcsb.arrivals_collide = r.boolean(v, at); }},
    {"feedback.policy",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) {
       s.feedback.policy =
           r.choice<PolicyKind>(v, at, {{"saliency", PolicyKind::kSaliency}, {"random", PolicyKind::kRandom}});
     }},
    {"feedback.threshold", [](const Reader& r, const json& v, const std::string& at,
                              Suite& s) { s.feedback.threshold = r.number(v, at, kNonNegative); }},
    {"feedback.max_ops_per_step", [](const Reader& r, const json& v, const std::string& at,
                                     Suite& s) { s.feedback.max_ops_per_step = whole(r, v, at, 1, 100000); }},
    {"feedback.evaluation_interval", [](const Reader& r, const json& v, const std::string& at,
                                        Suite& s) { s.feedback.evaluation_interval = whole(r, v, at, 1, 1000); }},
    {"feedback.global_motion_scale", [](const Reader& r, const json& v, const std::string& at,
                                        Suite& s) { s.feedback.global_motion_scale = r.number(v, at, kPositive); }},
    {"feedback.illumination", [](const Reader& r, const json& v, const std::string& at,
                                 Suite& s) { s.feedback.illumination = r.boolean(v, at); }},
    {"feedback.popping_charge", [](const Reader& r, const json& v, const std::string& at,
                                   Suite& s) { s.feedback.popping_charge = r.number(v, at, kNonNegative); }},
    {"feedback.interface_charge", [](const Reader& r, const json& v, const std::string& at,
                                     Suite& s) { s.feedback.interface_charge = r.number(v, at, kNonNegative); }},
    {"feedback.interface_tension", [](const Reader& r, const json& v, const std::string& at,
                                      Suite& s) { s.feedback.interface_tension = r.number(v, at, kNonNegative); }},
    {"feedback.pin_level_pull", [](const Reader& r, const json& v, const std::string& at,
                                   Suite& s) { s.feedback.pin_level_pull = r.number(v, at, kNonNegative); }},
    {"feedback.view",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) { s.feedback.view = r.boolean(v, at); }},
    {"feedback.view_motion_scale", [](const Reader& r, const json& v, const std::string& at,
                                      Suite& s) { s.feedback.view_motion_scale = r.number(v, at, kPositive); }},
    {"feedback.view_detail_px", [](const Reader& r, const json& v, const std::string& at,
                                   Suite& s) { s.feedback.view_detail_px = r.number(v, at, kPositive); }},
    {"feedback.view_static_share", [](const Reader& r, const json& v, const std::string& at,
                                      Suite& s) { s.feedback.view_static_share = r.number(v, at, kUnit); }},
    {"seed",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) { s.seed = r.unsigned_integer(v, at); }},
    {"dt",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) {
       s.world.dt = r.number(v, at, kFraction);
       s.solver.step_dt = s.world.dt;  // the step the compliant material's constants are made for
     }},
    {"gravity", [](const Reader& r, const json& v, const std::string& at,
                   Suite& s) { s.world.gravity = r.number(v, at, kSceneNonNegative); }},
    {"steps",
     [](const Reader& r, const json& v, const std::string& at, Suite& s) { s.steps = whole(r, v, at, 1, INT_MAX); }},
    {"warmup_steps", [](const Reader& r, const json& v, const std::string& at,
                        Suite& s) { s.warmup_steps = whole(r, v, at, 0, INT_MAX); }},
};

/// Settings of the suite file that exist but cannot be axes (see suite_axes.h for why).
constexpr std::string_view kFixedSettings[] = {"name",
                                               "description",
                                               "nets",
                                               "methods",
                                               "compression",
                                               "repetitions",
                                               "axes",
                                               "solver",
                                               "tcsb",
                                               "feedback",
                                               "fidelity",
                                               "feedback.light_direction",
                                               "feedback.parallel",
                                               "feedback.threads",
                                               "feedback.max_step_ms",
                                               "fidelity.enabled",
                                               "fidelity.rms_threshold_pct",
                                               "fidelity.pareto_targets",
                                               "fidelity.ablations",
                                               "fidelity.calibration"};

const AxisSetting* find_setting(std::string_view path) {
  for (const AxisSetting& s : kAxisSettings)
    if (s.path == path) return &s;
  return nullptr;
}

std::string axis_list() {
  std::string list;
  for (const AxisSetting& s : kAxisSettings) list += (list.empty() ? "" : ", ") + std::string(s.path);
  return list;
}

/// An axis value in a label: strings bare, numbers in their shortest form.
std::string value_text(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return fmt_number(v.get<double>());
  return v.dump();
}

/// "piterations=8,blend_steps=4": the last part of each path, in axis order.
std::string configuration_label(const std::vector<Axis>& axes, const std::vector<std::size_t>& index) {
  std::string label;
  for (std::size_t k = 0; k < axes.size(); ++k) {
    const std::string& path = axes[k].path;
    // Appended piecewise: GCC 12 misreports "literal" + string chains (-Wrestrict).
    if (k > 0) label += ',';
    label += path.substr(path.rfind('.') + 1);
    label += '=';
    label += value_text(axes[k].values[index[k]]);
  }
  return label;
}

}  // namespace

std::vector<std::string> axis_setting_paths() {
  std::vector<std::string> paths;
  for (const AxisSetting& s : kAxisSettings) paths.emplace_back(s.path);
  return paths;
}

void read_axis_setting(const Reader& r, const Object& object, const char* key, Suite& suite, bool required) {
  const std::string at = object.at(key);
  const AxisSetting* setting = find_setting(at);
  if (!setting) throw std::logic_error("read_axis_setting: " + at + " is not an axis-able setting");
  if (const json* v = object.find(key, required)) setting->read(r, *v, at, suite);
}

void parse_axes(const Reader& r, const json& axes, Suite& suite) {
  if (!axes.is_object()) r.fail("axes", "must be an object of setting paths and value lists, got " + describe(axes));
  if (axes.empty()) r.fail("axes", "must name at least one setting");
  for (const auto& item : axes.items()) {
    if (find_setting(item.key())) continue;
    const std::string at = key_path("axes", item.key());
    for (const std::string_view fixed : kFixedSettings) {
      if (item.key() == fixed)
        r.fail(at, "cannot be an axis (axes vary one case's scalar settings: " + axis_list() + ")");
    }
    r.fail(at, "unknown setting (an axis is one of: " + axis_list() + ")");
  }
  // Counted from the lists' lengths before any value is read: an axis of 10^5 values is refused at once, not after
  // checking each (and, once, comparing each with every other).
  double count = 1;  // a double: a typing error may make more configurations than a size_t holds
  std::string product;
  for (const AxisSetting& setting : kAxisSettings) {  // label order, whatever the file's
    const auto it = axes.find(std::string(setting.path));
    if (it == axes.end()) continue;
    const json& values = r.array(*it, key_path("axes", setting.path));
    count *= static_cast<double>(values.size());
    product += (product.empty() ? "" : " x ") + std::to_string(values.size());
  }
  if (count > static_cast<double>(kMaxConfigurations)) {
    r.fail("axes", product + " = " + fmt_number(count) + " configurations, more than the " +
                       std::to_string(kMaxConfigurations) + " a suite may have");
  }
  std::vector<Axis> parsed;
  for (const AxisSetting& setting : kAxisSettings) {
    const auto it = axes.find(std::string(setting.path));
    if (it == axes.end()) continue;
    const std::string at = key_path("axes", setting.path);
    const json& values = *it;
    Axis axis{std::string(setting.path), {}};
    for (std::size_t i = 0; i < values.size(); ++i) {
      Suite scratch;  // the value is only checked here; configuration_suite() applies it
      setting.read(r, values[i], index_path(at, i), scratch);
      for (std::size_t k = 0; k < i; ++k) {  // at most kMaxConfigurations values: quadratic is cheap here
        if (values[k] == values[i])
          r.fail(index_path(at, i), "duplicate value " + describe(values[i]) + " (also " + index_path(at, k) + ")");
      }
      axis.values.push_back(values[i]);
    }
    parsed.push_back(std::move(axis));
  }
  suite.axes = std::move(parsed);
  suite.configurations.clear();
  std::vector<std::size_t> index(suite.axes.size(), 0);
  for (std::size_t n = 0; n < static_cast<std::size_t>(count); ++n) {
    suite.configurations.push_back({index, configuration_label(suite.axes, index)});
    for (std::size_t k = suite.axes.size(); k-- > 0;) {  // the last axis varies fastest
      if (++index[k] < suite.axes[k].values.size()) break;
      index[k] = 0;
    }
  }
}

Suite configuration_suite(const Suite& suite, std::size_t configuration) {
  Suite out = suite;
  if (suite.configurations.empty()) return out;
  const Reader r(suite.path.string());
  const Configuration& c = suite.configurations.at(configuration);
  for (std::size_t k = 0; k < suite.axes.size(); ++k) {
    const Axis& axis = suite.axes[k];
    find_setting(axis.path)->read(r, axis.values[c.value_index[k]], axis.path, out);  // checked when parsed
  }
  out.axes.clear();
  out.configurations.clear();
  out.run_units.clear();
  if (!suite.run_units.empty()) {
    out.run_units.resize(suite.nets.size());
    for (std::size_t net = 0; net < suite.nets.size(); ++net) out.run_units[net] = runs_unit(suite, configuration, net);
  }
  out.run_repetitions.clear();
  if (!suite.run_repetitions.empty()) {
    const auto repetitions = static_cast<std::size_t>(suite.repetitions);
    out.run_repetitions.resize(suite.nets.size() * repetitions);
    for (std::size_t net = 0; net < suite.nets.size(); ++net)
      for (std::size_t r = 0; r < repetitions; ++r)
        out.run_repetitions[net * repetitions + r] = runs_repetition(suite, configuration, net, static_cast<int>(r));
  }
  return out;
}

std::vector<Suite> configuration_suites(const Suite& suite) {
  std::vector<Suite> suites;
  for (std::size_t c = 0; c < configuration_count(suite); ++c) suites.push_back(configuration_suite(suite, c));
  return suites;
}

nlohmann::ordered_json configuration_values(const Suite& suite, std::size_t configuration) {
  nlohmann::ordered_json values = nlohmann::ordered_json::object();
  if (suite.configurations.empty()) return values;
  const Configuration& c = suite.configurations.at(configuration);
  for (std::size_t k = 0; k < suite.axes.size(); ++k)
    values[suite.axes[k].path] = nlohmann::ordered_json::parse(suite.axes[k].values[c.value_index[k]].dump());
  return values;
}

}  // namespace tcsb
