// Flag values the way a careless user types them: an empty value ("--out ''", "--repetitions ''") or an empty
// element of a list ("--compression 0.5,,0.3") is an error naming the flag, never silently "no value" or dropped
// (CLI11 drops empty list elements and takes "" as a value).
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace tcsb::cli {

/// Adds `name` taking a comma-separated list of numbers into `values`: an empty list, an empty element or one that
/// is not a number is a parse error (exit 2) naming the flag.
CLI::Option* add_list_option(CLI::App& app, const std::string& name, std::vector<double>& values,
                             const std::string& description);

/// As above, for whole numbers.
CLI::Option* add_list_option(CLI::App& app, const std::string& name, std::vector<int>& values,
                             const std::string& description);

/// Makes every option of `app` and of its subcommands that takes a value reject an empty one, naming the option.
/// Call after every option is registered.
void reject_empty_values(CLI::App& app);

}  // namespace tcsb::cli
