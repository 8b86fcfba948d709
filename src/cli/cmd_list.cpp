// `tcsb list`: the bundled suites at a glance. Read leniently (not through parse_suite) so a suite too large for
// this machine, or a broken one, is still listed instead of hiding the others.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/json_file.h"
#include "base/terminal_text.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "report/text_table.h"
#include "suite/suite.h"

namespace tcsb::cli {
namespace {

/// The description's first line, cut at a word near 100 characters: descriptions are often one long paragraph.
std::string first_line(const std::string& text) {
  constexpr std::size_t kMax = 100;
  std::string line = text.substr(0, text.find('\n'));
  if (line.size() <= kMax) return line;
  const std::size_t cut = line.rfind(' ', kMax - 3);
  return line.substr(0, cut == std::string::npos ? kMax - 3 : cut) + "...";
}

std::vector<std::string> describe(const std::string& name) {
  const std::filesystem::path path = suites_dir() / (name + ".json");
  nlohmann::json j;
  try {
    j = read_json_file<nlohmann::json>(path, kSuiteJsonLimits);  // bounded: a huge or hostile file cannot stall it
  } catch (const InputError&) {
  }
  if (!j.is_object()) return {name, "?", "?", "(not a valid suite: run `tcsb validate " + name + "`)"};
  const auto nets = j.find("nets");
  std::string methods;
  if (const auto m = j.find("methods"); m != j.end() && m->is_array()) {
    for (const auto& method : *m) {
      methods += (methods.empty() ? "" : ",") + (method.is_string() ? method.get<std::string>() : "?");
    }
  }
  const auto description = j.find("description");
  return {name, nets != j.end() && nets->is_array() ? std::to_string(nets->size()) : "?", methods,
          description != j.end() && description->is_string() ? first_line(description->get<std::string>()) : ""};
}

}  // namespace

CLI::App* add_list_command(CLI::App& app) { return app.add_subcommand("list", "List the bundled suites"); }

int list_command() {
  const std::vector<std::string> names = bundled_suite_names();
  if (names.empty()) throw UsageError("no bundled suites in " + suites_dir().string() + " (set TCSB_SUITES_DIR?)");
  TextTable table({{"suite", TextTable::Align::kLeft},
                   {"nets"},
                   {"methods", TextTable::Align::kLeft},
                   {"description", TextTable::Align::kLeft}});
  for (const std::string& name : names) table.add_row(describe(name));
  table.print(std::cout, 0);
  std::cout << "Suites directory: " << terminal_safe(suites_dir().string()) << '\n';
  return kExitOk;
}

}  // namespace tcsb::cli
