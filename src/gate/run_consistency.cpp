#include "gate/run_consistency.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// The suite block's nets: name -> width x height. Every field is required, as the result schema says.
std::map<std::string, std::int64_t> net_sizes(const ResultView& result) {
  const auto nets = result.suite.find("nets");
  if (nets == result.suite.end() || !nets->is_array() || nets->empty())
    throw InputError(result.file, "suite.nets", "missing or empty (a run records the nets it ran)");
  std::map<std::string, std::int64_t> sizes;
  for (std::size_t i = 0; i < nets->size(); ++i) {
    const ojson& n = (*nets)[i];
    const std::string at = "suite.nets[" + std::to_string(i) + "]";
    if (!n.is_object() || !n.contains("name") || !n["name"].is_string() || !n.contains("width") ||
        !n["width"].is_number_integer() || !n.contains("height") || !n["height"].is_number_integer())
      throw InputError(result.file, at, "must have a name, a width and a height");
    const std::int64_t width = n["width"].get<std::int64_t>(), height = n["height"].get<std::int64_t>();
    if (width < 1 || height < 1 || width > 1000000 || height > 1000000)
      throw InputError(result.file, at, "width and height must be in [1, 1000000]");
    if (!sizes.emplace(n["name"].get<std::string>(), width * height).second)
      throw InputError(result.file, at + ".name", "net " + n["name"].dump() + " listed twice");
  }
  return sizes;
}

/// Whether `result` is a shard split by repetition: it holds some of the suite's repetitions of a case, keeping their
/// numbers (which ones, `tcsb merge` checks against the shard's index).
bool holds_some_repetitions(const ResultView& result) {
  const ojson* shard =
      result.context.is_object() && result.context.contains("shard") ? &result.context["shard"] : nullptr;
  return shard && shard->is_object() && shard->value("split", "") == "repetitions";
}

/// Repetitions numbered 0 .. k-1 once each, k >= the suite's repetitions; in a shard split by repetition, some of the
/// suite's repetitions 0 .. R-1, once each.
void check_repetitions(const ResultView& result, const CaseView& c, const std::string& path) {
  const std::size_t count = c.repetitions.size();
  const bool some = holds_some_repetitions(result);
  const std::size_t numbers = some ? static_cast<std::size_t>(std::max(result.repetitions, 0)) : count;
  std::vector<bool> seen(numbers, false);
  for (std::size_t k = 0; k < count; ++k) {
    const int number = c.repetitions[k].repetition;
    const std::string at = path + ".repetitions[" + std::to_string(k) + "].repetition";
    if (number < 0 || static_cast<std::size_t>(number) >= numbers)
      throw InputError(result.file, at,
                       some ? std::to_string(number) + ", but the suite ran repetitions 0 to " +
                                  std::to_string(numbers) + " - 1"
                            : std::to_string(number) + ", but the case has " + std::to_string(count) +
                                  " repetitions (a run numbers them from 0, once each)");
    if (seen[static_cast<std::size_t>(number)])
      throw InputError(result.file, at, "repetition " + std::to_string(number) + " appears twice");
    seen[static_cast<std::size_t>(number)] = true;
  }
  if (!some && count < static_cast<std::size_t>(result.repetitions))
    throw InputError(result.file, path + ".repetitions",
                     std::to_string(count) + " repetitions, but the suite ran " + std::to_string(result.repetitions) +
                         " of every case (one is missing)");
}

}  // namespace

void check_instruction_counts(const ResultView& result) {
  if (result.measure != "instructions") return;
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseView& c = result.cases[i];
    const std::string path = "cases[" + std::to_string(i) + "].instructions";
    if (!c.instructions)
      throw InputError(result.file, path,
                       "missing: a run with --measure instructions counts every case (case " + c.label + ")");
    const InstructionsView& n = *c.instructions;
    std::int64_t ok = 0;
    for (const RepetitionView& r : c.repetitions) ok += r.status == "ok";
    // Each timed step moves every simulated node at least once: far fewer instructions than that were not counted.
    const double nodes = std::max(1.0, c.mean_nodes.value_or(1.0));
    const double least = static_cast<double>(ok) * std::max(result.steps, 1) * nodes;
    if (ok > 0 && static_cast<double>(n.total) < least)
      throw InputError(result.file, path + ".total",
                       std::to_string(n.total) + ", but " + std::to_string(ok) + " ok repetition(s) of " +
                           std::to_string(result.steps) + " steps of " + c.label +
                           " take at least one instruction per node and step (" +
                           std::to_string(static_cast<std::int64_t>(least)) + ")");
    if (ok == 0 && n.total != 0)
      throw InputError(result.file, path + ".total",
                       std::to_string(n.total) + ", but case " + c.label + " has no ok repetition to count");
  }
}

void check_run_is_possible(const ResultView& result) {
  const std::map<std::string, std::int64_t> sizes = net_sizes(result);
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseView& c = result.cases[i];
    const std::string path = "cases[" + std::to_string(i) + "]";
    const auto net = sizes.find(c.net);
    if (net == sizes.end())
      throw InputError(result.file, path + ".net", "\"" + c.net + "\" is not a net of the suite (suite.nets)");
    if (c.net_nodes && *c.net_nodes != net->second)
      throw InputError(result.file, path + ".net_nodes",
                       std::to_string(*c.net_nodes) + ", but net " + c.net + " has " + std::to_string(net->second) +
                           " nodes (its width x height)");
    check_repetitions(result, c, path);
  }
  check_instruction_counts(result);
}

}  // namespace tcsb
