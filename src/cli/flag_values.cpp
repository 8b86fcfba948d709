#include "cli/flag_values.h"

#include <CLI/CLI.hpp>
#include <charconv>
#include <string_view>

namespace tcsb::cli {
namespace {

template <typename T>
std::vector<T> parse_list(const std::string& flag, const std::string& text, const char* kind) {
  if (text.empty()) throw CLI::ValidationError(flag, "must not be empty");
  std::vector<T> values;
  std::string_view rest = text;
  for (std::size_t element = 1;; ++element) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    T value{};
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty()) {
      throw CLI::ValidationError(flag, "element " + std::to_string(element) + " of \"" + text + "\" is empty");
    }
    if (ec != std::errc() || end != item.data() + item.size()) {
      throw CLI::ValidationError(flag, "element " + std::to_string(element) + " (\"" + std::string(item) +
                                           "\") is not " + kind);
    }
    values.push_back(value);
    if (comma == std::string_view::npos) return values;
    rest.remove_prefix(comma + 1);
  }
}

template <typename T>
CLI::Option* add_list(CLI::App& app, const std::string& name, std::vector<T>& values, const std::string& description,
                      const char* kind) {
  return app
      .add_option_function<std::string>(
          name, [&values, name, kind](const std::string& text) { values = parse_list<T>(name, text, kind); },
          description)
      ->type_name("LIST");
}

}  // namespace

CLI::Option* add_list_option(CLI::App& app, const std::string& name, std::vector<double>& values,
                             const std::string& description) {
  return add_list(app, name, values, description, "a number");
}

CLI::Option* add_list_option(CLI::App& app, const std::string& name, std::vector<int>& values,
                             const std::string& description) {
  return add_list(app, name, values, description, "a whole number");
}

void reject_empty_values(CLI::App& app) {
  const CLI::Validator non_empty(
      [](std::string& value) { return value.empty() ? std::string("must not be empty") : std::string(); }, "");
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_size_max() > 0) option->check(non_empty);  // flags (--quiet) take no value
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) reject_empty_values(*sub);
}

}  // namespace tcsb::cli
