#include "gate/result_view.h"

#include <cmath>
#include <limits>

#include "analysis/relative_change.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// Typed access to one document that throws ResultFileError naming the file and the field.
class Fields {
 public:
  explicit Fields(const std::string& file) : file_(file) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw ResultFileError(file_, path, problem);
  }
  const ojson& member(const ojson& object, const std::string& parent, const char* key) const {
    if (!object.is_object()) fail(parent, "must be an object");
    const auto it = object.find(key);
    if (it == object.end()) fail(join(parent, key), "missing");
    return *it;
  }
  const ojson& object(const ojson& parent, const std::string& path, const char* key) const {
    const ojson& j = member(parent, path, key);
    if (!j.is_object()) fail(join(path, key), "must be an object");
    return j;
  }
  const ojson& array(const ojson& parent, const std::string& path, const char* key) const {
    const ojson& j = member(parent, path, key);
    if (!j.is_array()) fail(join(path, key), "must be an array");
    return j;
  }
  std::string string(const ojson& parent, const std::string& path, const char* key) const {
    const ojson& j = member(parent, path, key);
    if (!j.is_string()) fail(join(path, key), "must be a string");
    return j.get<std::string>();
  }
  /// A finite number, or nullopt for null (the files write null where nothing was measured).
  std::optional<double> number_or_null(const ojson& parent, const std::string& path, const char* key) const {
    const ojson& j = member(parent, path, key);
    if (j.is_null()) return std::nullopt;
    if (!j.is_number()) fail(join(path, key), "must be a number or null");
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(join(path, key), "must be finite");
    return v;
  }
  /// number_or_null that is also >= 0: a count or a mean of counts (N, L, I), or a spread, is never negative.
  std::optional<double> non_negative_or_null(const ojson& parent, const std::string& path, const char* key) const {
    const std::optional<double> v = number_or_null(parent, path, key);
    if (v && *v < 0.0) fail(join(path, key), "must be >= 0, got " + ojson(*v).dump());
    return v;
  }
  std::int64_t integer(const ojson& parent, const std::string& path, const char* key, std::int64_t lo,
                       std::int64_t hi) const {
    const ojson& j = member(parent, path, key);
    const std::string range = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    std::int64_t v = 0;
    if (j.is_number_unsigned()) {
      if (j.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) fail(join(path, key), range);
      v = static_cast<std::int64_t>(j.get<std::uint64_t>());
    } else if (j.is_number_integer()) {
      v = j.get<std::int64_t>();
    } else if (j.is_number_float() && is_exact_integer(j.get<double>())) {
      v = static_cast<std::int64_t>(j.get<double>());  // 3.0 is an integer in JSON
    } else {
      fail(join(path, key), range);
    }
    if (v < lo || v > hi) fail(join(path, key), range);
    return v;
  }
  std::optional<int> integer_or_null(const ojson& parent, const std::string& path, const char* key) const {
    if (member(parent, path, key).is_null()) return std::nullopt;
    return static_cast<int>(integer(parent, path, key, 0, std::numeric_limits<int>::max()));
  }
  /// Integral and below 2^53, so the conversion to an integer is exact.
  static bool is_exact_integer(double d) { return std::trunc(d) == d && std::abs(d) < 0x1p53; }
  static std::string join(const std::string& parent, const char* key) {
    return parent.empty() ? std::string(key) : parent + "." + key;
  }
  static std::string index(const std::string& parent, std::size_t i) { return parent + "[" + std::to_string(i) + "]"; }

 private:
  const std::string& file_;
};

/// A repetition's mean step time: a step takes time, so a recorded one is > 0, and an ok repetition timed every
/// step, so it has one. Anything else cannot come from a run, and the gate must not read it as faster or slower.
std::optional<double> read_step_time(const Fields& f, const ojson& j, const std::string& path, bool ok) {
  const std::optional<double> ms = f.number_or_null(j, path, "mean_step_ms");
  const std::string field = Fields::join(path, "mean_step_ms");
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
  if (v.own > kMax - v.bullet || v.own + v.bullet != v.total)
    f.fail(Fields::join(path, "total"), "must be own + bullet");
  const ojson& functions = f.array(j, path, "functions");
  const std::string functions_path = Fields::join(path, "functions");
  for (std::size_t i = 0; i < functions.size(); ++i) {
    const std::string function_path = Fields::index(functions_path, i);
    v.functions.emplace_back(f.string(functions[i], function_path, "name"),
                             f.integer(functions[i], function_path, "instructions", 0, kMax));
  }
  return v;
}

CaseView read_case(const Fields& f, const ojson& j, const std::string& path) {
  if (!j.is_object()) f.fail(path, "must be an object");
  CaseView c;
  c.label = f.string(j, path, "label");
  c.net = f.string(j, path, "net");
  c.method = f.string(j, path, "method");
  if (j.contains("configuration"))  // optional: only with axes
    c.configuration = f.string(f.object(j, path, "configuration"), Fields::join(path, "configuration"), "label");
  c.compression = f.number_or_null(j, path, "compression");
  if (j.contains("net_nodes"))
    c.net_nodes = f.integer(j, path, "net_nodes", 0, std::numeric_limits<std::int64_t>::max());
  c.status = f.string(j, path, "status");
  c.mean_nodes = f.non_negative_or_null(j, path, "mean_nodes");
  c.mean_links = f.non_negative_or_null(j, path, "mean_links");
  c.mean_interpolations = f.non_negative_or_null(j, path, "mean_interpolations");
  const std::string step_path = Fields::join(path, "step_ms");
  const ojson& step_ms = f.object(j, path, "step_ms");
  c.median_step_ms = f.non_negative_or_null(step_ms, step_path, "median");
  c.stddev_step_ms = f.non_negative_or_null(step_ms, step_path, "stddev");
  c.cv_step_ms = f.non_negative_or_null(step_ms, step_path, "cv");
  const ojson& reps = f.array(j, path, "repetitions");
  const std::string reps_path = Fields::join(path, "repetitions");
  for (std::size_t i = 0; i < reps.size(); ++i) {
    const std::string rep_path = Fields::index(reps_path, i);
    if (!reps[i].is_object()) f.fail(rep_path, "must be an object");
    c.repetitions.push_back(read_repetition(f, reps[i], rep_path));
  }
  if (j.contains("instructions"))
    c.instructions = read_instructions(f, f.object(j, path, "instructions"), Fields::join(path, "instructions"));
  return c;
}

}  // namespace

ResultView read_result(const ojson& doc, const std::string& file) {
  const Fields f(file);
  if (!doc.is_object()) f.fail("", "not a tcsb result (the top level is not a JSON object)");
  const auto tool = doc.find("tool");
  if (tool == doc.end() || *tool != "tcsb") f.fail("tool", "not a tcsb result (\"tool\" is not \"tcsb\")");
  ResultView r;
  r.file = file;
  r.schema_version = static_cast<int>(f.integer(doc, "", "schema_version", 1, std::numeric_limits<int>::max()));
  if (doc.contains("measure")) {
    r.measure = f.string(doc, "", "measure");
    if (r.measure != "time" && r.measure != "instructions") f.fail("measure", "must be \"time\" or \"instructions\"");
  }
  r.context = f.object(doc, "", "context");
  r.suite = f.object(doc, "", "suite");
  r.steps = static_cast<int>(f.integer(r.suite, "suite", "steps", 1, std::numeric_limits<int>::max()));
  r.repetitions = static_cast<int>(f.integer(r.suite, "suite", "repetitions", 1, std::numeric_limits<int>::max()));
  const ojson& cases = f.array(doc, "", "cases");
  for (std::size_t i = 0; i < cases.size(); ++i) r.cases.push_back(read_case(f, cases[i], Fields::index("cases", i)));
  return r;
}

std::optional<std::size_t> plain_case_of(const ResultView& result, std::size_t index) {
  if (index >= result.cases.size()) return std::nullopt;
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseView &c = result.cases[i], &of = result.cases[index];
    if (c.net == of.net && c.configuration == of.configuration && c.method == "plain") return i;
  }
  return std::nullopt;
}

std::optional<std::size_t> equal_plain_case_of(const ResultView& result, std::size_t index) {
  if (index >= result.cases.size()) return std::nullopt;
  const CaseView& of = result.cases[index];
  if (of.method != "tcsb" || !of.compression) return std::nullopt;
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseView& c = result.cases[i];
    if (c.net == of.net && c.configuration == of.configuration && c.method == "plain_equal" && c.compression &&
        std::abs(*c.compression - *of.compression) <= 1e-9)
      return i;
  }
  return std::nullopt;
}

std::vector<PairedStepTimes> paired_step_times(const ResultView& result, std::size_t index, std::size_t base_index) {
  std::vector<PairedStepTimes> pairs;
  if (index >= result.cases.size() || base_index >= result.cases.size()) return pairs;
  const CaseView& base = result.cases[base_index];
  for (const RepetitionView& r : result.cases[index].repetitions) {
    if (r.status != "ok" || !r.mean_step_ms) continue;
    for (const RepetitionView& b : base.repetitions) {
      if (b.repetition != r.repetition) continue;
      if (b.status == "ok" && b.mean_step_ms) pairs.push_back({*r.mean_step_ms, *b.mean_step_ms, r.process});
      break;
    }
  }
  return pairs;
}

std::vector<double> step_ratios(const std::vector<PairedStepTimes>& pairs) {
  std::vector<double> ratios;
  for (const PairedStepTimes& p : pairs) {
    if (const auto q = safe_ratio(p.case_ms, p.base_ms)) ratios.push_back(*q);
  }
  return ratios;
}

std::vector<double> paired_step_ratios(const ResultView& result, std::size_t index, std::size_t base_index) {
  return step_ratios(paired_step_times(result, index, base_index));
}

std::vector<double> ok_step_times(const CaseView& c) {
  std::vector<double> times;
  for (const RepetitionView& r : c.repetitions) {
    if (r.status == "ok" && r.mean_step_ms) times.push_back(*r.mean_step_ms);
  }
  return times;
}

}  // namespace tcsb
