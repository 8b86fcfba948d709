#include "suite/suite_axes.h"

#include <algorithm>
#include <iterator>
#include <string_view>

#include "suite/suite_settings_table.h"

namespace tcsb {
namespace {

using namespace suite_fields;

/// The table's rows a sweep axis may vary, in label order.
std::vector<const SuiteSetting*> axis_settings() {
  std::vector<const SuiteSetting*> rows;
  for (const SuiteSetting& row : suite_settings())
    if (row.axis != kNoAxis) rows.push_back(&row);
  std::sort(rows.begin(), rows.end(), [](const SuiteSetting* a, const SuiteSetting* b) { return a->axis < b->axis; });
  return rows;
}

const SuiteSetting* find_axis_setting(std::string_view path) {
  const SuiteSetting* row = find_suite_setting(path);
  return row && row->axis != kNoAxis ? row : nullptr;
}

/// Keys of the suite file that are not scalar settings of the table, yet name something an axis might be taken for.
constexpr std::string_view kStructuredKeys[] = {"name",
                                                "description",
                                                "nets",
                                                "methods",
                                                "compression",
                                                "axes",
                                                "solver",
                                                "tcsb",
                                                "feedback",
                                                "fidelity",
                                                "fidelity.enabled",
                                                "fidelity.rms_threshold_pct",
                                                "fidelity.pareto_targets",
                                                "fidelity.ablations",
                                                "fidelity.calibration"};

/// Whether `path`, which no axis row took, names a setting or block of the suite file (so it "cannot be an axis",
/// rather than being unknown).
bool is_fixed_setting(std::string_view path) {
  if (find_suite_setting(path)) return true;
  return std::find(std::begin(kStructuredKeys), std::end(kStructuredKeys), path) != std::end(kStructuredKeys);
}

std::string axis_list() {
  std::string list;
  for (const SuiteSetting* row : axis_settings()) list += (list.empty() ? "" : ", ") + std::string(row->path);
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
  for (const SuiteSetting* row : axis_settings()) paths.emplace_back(row->path);
  return paths;
}

void parse_axes(const Reader& r, const json& axes, Suite& suite) {
  if (!axes.is_object()) r.fail("axes", "must be an object of setting paths and value lists, got " + describe(axes));
  if (axes.empty()) r.fail("axes", "must name at least one setting");
  for (const auto& item : axes.items()) {
    if (find_axis_setting(item.key())) continue;
    const std::string at = key_path("axes", item.key());
    if (is_fixed_setting(item.key()))
      r.fail(at, "cannot be an axis (axes vary one case's scalar settings: " + axis_list() + ")");
    r.fail(at, "unknown setting (an axis is one of: " + axis_list() + ")");
  }
  // Counted from the lists' lengths before any value is read: an axis of 10^5 values is refused at once, not after
  // checking each (and, once, comparing each with every other).
  double count = 1;  // a double: a typing error may make more configurations than a size_t holds
  std::string product;
  const std::vector<const SuiteSetting*> settings = axis_settings();
  for (const SuiteSetting* setting : settings) {  // label order, whatever the file's
    const auto it = axes.find(std::string(setting->path));
    if (it == axes.end()) continue;
    const json& values = r.array(*it, key_path("axes", setting->path));
    count *= static_cast<double>(values.size());
    product += (product.empty() ? "" : " x ") + std::to_string(values.size());
  }
  if (count > static_cast<double>(kMaxConfigurations)) {
    r.fail("axes", product + " = " + fmt_number(count) + " configurations, more than the " +
                       std::to_string(kMaxConfigurations) + " a suite may have");
  }
  std::vector<Axis> parsed;
  for (const SuiteSetting* setting : settings) {
    const auto it = axes.find(std::string(setting->path));
    if (it == axes.end()) continue;
    const std::string at = key_path("axes", setting->path);
    const json& values = *it;
    Axis axis{std::string(setting->path), {}};
    for (std::size_t i = 0; i < values.size(); ++i) {
      Suite scratch;  // the value is only checked here; configuration_suite() applies it
      read_suite_setting(*setting, r, values[i], index_path(at, i), scratch);
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
    // (checked when parsed)
    read_suite_setting(*find_axis_setting(axis.path), r, axis.values[c.value_index[k]], axis.path, out);
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
