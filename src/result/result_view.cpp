#include "result/result_view.h"

#include <cmath>
#include <limits>
#include <tuple>

#include "analysis/relative_change.h"
#include "base/case_pairing.h"
#include "base/json_fields.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// Typed access to one document that throws InputError naming the file and the field (base/json_fields.h).
using Fields = JsonFields<ojson>;

/// A repetition's mean step time: a step takes time, so a recorded one is > 0, and an ok repetition timed every
/// step, so it has one. Anything else cannot come from a run, and the gate must not read it as faster or slower.
std::optional<double> read_step_time(const Fields& f, const ojson& j, const std::string& path, bool ok) {
  const std::optional<double> ms = f.number_or_null(j, path, "mean_step_ms");
  const std::string field = key_path(path, "mean_step_ms");
  if (!ms && ok) f.fail(field, "null, but the repetition's status is \"ok\" (an ok repetition has a step time)");
  if (ms && !(*ms > 0.0)) f.fail(field, "must be > 0 (a step takes time), got " + ojson(*ms).dump());
  return ms;
}

RepetitionView read_repetition(const Fields& f, const ojson& j, const std::string& path) {
  RepetitionView r;
  r.repetition = static_cast<int>(f.integer(j, path, "repetition", 0, std::numeric_limits<int>::max()));
  r.status = f.string(j, path, "status");
  r.diverged_step = f.integer_or_null(j, path, "diverged_step");
  r.mean_step_ms = read_step_time(f, j, path, r.status == "ok");
  r.mean_nodes = f.non_negative_or_null(j, path, "mean_nodes");
  r.mean_links = f.non_negative_or_null(j, path, "mean_links");
  r.mean_interpolations = f.non_negative_or_null(j, path, "mean_interpolations");
  r.operations = f.integer(j, path, "operations", 0, std::numeric_limits<std::int64_t>::max());
  r.final_state_hash = f.string(j, path, "final_state_hash");
  if (j.contains("process"))
    r.process = static_cast<int>(f.integer(j, path, "process", 1, std::numeric_limits<int>::max()));
  return r;
}

/// A case's `instructions` object: counts (own + bullet = total) and the functions.
InstructionsView read_instructions(const Fields& f, const ojson& j, const std::string& path) {
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  InstructionsView v;
  v.own = f.integer(j, path, "own", 0, kMax);
  v.bullet = f.integer(j, path, "bullet", 0, kMax);
  v.total = f.integer(j, path, "total", 0, kMax);
  if (v.own > kMax - v.bullet || v.own + v.bullet != v.total) f.fail(key_path(path, "total"), "must be own + bullet");
  const ojson& functions = f.array(j, path, "functions");
  const std::string functions_path = key_path(path, "functions");
  for (std::size_t i = 0; i < functions.size(); ++i) {
    const std::string function_path = index_path(functions_path, i);
    v.functions.emplace_back(f.string(functions[i], function_path, "name"),
                             f.integer(functions[i], function_path, "instructions", 0, kMax));
  }
  return v;
}

CaseView read_case(const Fields& f, const ojson& j, const std::string& path) {
  f.object(j, path);
  CaseView c;
  c.label = f.string(j, path, "label");
  c.net = f.string(j, path, "net");
  c.method = f.string(j, path, "method");
  if (j.contains("configuration"))  // optional: only with axes
    c.configuration = f.string(f.object(j, path, "configuration"), key_path(path, "configuration"), "label");
  c.compression = f.number_or_null(j, path, "compression");
  if (j.contains("net_nodes"))
    c.net_nodes = f.integer(j, path, "net_nodes", 0, std::numeric_limits<std::int64_t>::max());
  c.status = f.string(j, path, "status");
  c.mean_nodes = f.non_negative_or_null(j, path, "mean_nodes");
  c.mean_links = f.non_negative_or_null(j, path, "mean_links");
  c.mean_interpolations = f.non_negative_or_null(j, path, "mean_interpolations");
  const std::string step_path = key_path(path, "step_ms");
  const ojson& step_ms = f.object(j, path, "step_ms");
  // count, mean and ratio_vs_plain: hand-made documents (the gate's tests) may leave them out.
  if (step_ms.contains("count"))
    c.step_ms_count = f.integer(step_ms, step_path, "count", 0, std::numeric_limits<std::int64_t>::max());
  if (step_ms.contains("mean")) c.mean_step_ms = f.non_negative_or_null(step_ms, step_path, "mean");
  c.median_step_ms = f.non_negative_or_null(step_ms, step_path, "median");
  c.stddev_step_ms = f.non_negative_or_null(step_ms, step_path, "stddev");
  c.cv_step_ms = f.non_negative_or_null(step_ms, step_path, "cv");
  if (j.contains("ratio_vs_plain")) c.ratio_vs_plain = f.non_negative_or_null(j, path, "ratio_vs_plain");
  const ojson& reps = f.array(j, path, "repetitions");
  const std::string reps_path = key_path(path, "repetitions");
  for (std::size_t i = 0; i < reps.size(); ++i) {
    const std::string rep_path = index_path(reps_path, i);
    f.object(reps[i], rep_path);
    c.repetitions.push_back(read_repetition(f, reps[i], rep_path));
  }
  if (j.contains("instructions"))
    c.instructions = read_instructions(f, f.object(j, path, "instructions"), key_path(path, "instructions"));
  return c;
}

/// A case as the pairing rule sees it (base/case_pairing.h): its net and configuration, and its method.
auto pairing_key(const CaseView& c) {
  const PairingRole role = c.method == "plain"         ? PairingRole::kPlain
                           : c.method == "plain_equal" ? PairingRole::kPlainEqual
                           : c.method == "tcsb"        ? PairingRole::kTcsb
                                                       : PairingRole::kOther;
  return PairingKey{std::tie(c.net, c.configuration), role, c.compression};
}

}  // namespace

void check_tcsb_document(const ojson& doc, const std::string& file) {
  if (!doc.is_object()) throw InputError(file, "", "not a tcsb result (the top level is not a JSON object)");
  const auto tool = doc.find("tool");
  if (tool == doc.end() || *tool != "tcsb")
    throw InputError(file, "tool", "not a tcsb result (\"tool\" is not \"tcsb\")");
}

ResultView read_result(const ojson& doc, const std::string& file) {
  check_tcsb_document(doc, file);
  const Fields f(file);
  ResultView r;
  r.file = file;
  r.schema_version = static_cast<int>(f.integer(doc, "", "schema_version", 1, std::numeric_limits<int>::max()));
  if (doc.contains("measure")) {
    r.measure = f.string(doc, "", "measure");
    if (r.measure != "time" && r.measure != "instructions") f.fail("measure", "must be \"time\" or \"instructions\"");
  }
  r.context = f.object(doc, "", "context");
  r.suite = f.object(doc, "", "suite");
  // A setting suites gained after a result was written: the run had its default, so a result from before it reads
  // (and compares, merges) as one that records the default.
  if (!r.suite.contains("interleave_across_nets")) r.suite["interleave_across_nets"] = false;
  r.steps = static_cast<int>(f.integer(r.suite, "suite", "steps", 1, std::numeric_limits<int>::max()));
  r.repetitions = static_cast<int>(f.integer(r.suite, "suite", "repetitions", 1, std::numeric_limits<int>::max()));
  const ojson& cases = f.array(doc, "", "cases");
  for (std::size_t i = 0; i < cases.size(); ++i) r.cases.push_back(read_case(f, cases[i], index_path("cases", i)));
  return r;
}

std::optional<std::size_t> plain_case_of(const ResultView& result, std::size_t index) {
  return plain_partner(result.cases, index, pairing_key);
}

std::optional<std::size_t> equal_plain_case_of(const ResultView& result, std::size_t index) {
  return equal_plain_partner(result.cases, index, pairing_key);
}

std::vector<PairedStepTimes> paired_step_times(const ResultView& result, std::size_t index, std::size_t base_index) {
  std::vector<PairedStepTimes> pairs;
  if (index >= result.cases.size() || base_index >= result.cases.size()) return pairs;
  for_each_repetition_pair(result.cases[index].repetitions, result.cases[base_index].repetitions,
                           [&](const RepetitionView& r, const RepetitionView& b) {
                             if (r.mean_step_ms && b.mean_step_ms)
                               pairs.push_back({*r.mean_step_ms, *b.mean_step_ms, r.process});
                           });
  return pairs;
}

MeasuredValues paired_step_ratio_values(const ResultView& result, std::size_t index, std::size_t base_index) {
  MeasuredValues out;
  for (const PairedStepTimes& p : paired_step_times(result, index, base_index)) {
    if (const auto q = safe_ratio(p.case_ms, p.base_ms)) {
      out.values.push_back(*q);
      out.process.push_back(p.process);
    }
  }
  return out;
}

std::vector<double> paired_step_ratios(const ResultView& result, std::size_t index, std::size_t base_index) {
  return paired_step_ratio_values(result, index, base_index).values;
}

MeasuredValues ok_step_time_values(const CaseView& c) {
  MeasuredValues out;
  for (const RepetitionView& r : c.repetitions) {
    if (r.status == "ok" && r.mean_step_ms) {
      out.values.push_back(*r.mean_step_ms);
      out.process.push_back(r.process);
    }
  }
  return out;
}

std::vector<double> ok_step_times(const CaseView& c) { return ok_step_time_values(c).values; }

}  // namespace tcsb
