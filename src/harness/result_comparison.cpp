#include "harness/result_comparison.h"

#include <charconv>
#include <map>

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// At most 60 characters for a one-line message, "..." marking a cut.
std::string shorten(std::string text) { return text.size() > 60 ? text.substr(0, 57) + "..." : text; }

/// A JSON value for a one-line message: short, never multi-line.
std::string brief(const ojson& j) { return shorten(j.dump(-1, ' ', false, ojson::error_handler_t::replace)); }

/// The first place where two JSON values differ, as "path: A vs B", or "" when they are equal. Objects are
/// compared key by key whatever their order.
std::string first_difference(const ojson& a, const ojson& b, const std::string& path) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      const std::string sub = path + "." + key;
      const auto it = b.find(key);
      if (it == b.end()) return sub + ": " + brief(value) + " vs absent";
      if (std::string d = first_difference(value, *it, sub); !d.empty()) return d;
    }
    for (const auto& [key, value] : b.items()) {
      if (!a.contains(key)) return path + "." + key + ": absent vs " + brief(value);
    }
    return "";
  }
  if (a.is_array() && b.is_array()) {
    if (a.size() != b.size()) {
      return path + ": " + std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " entries (" + brief(a) +
             " vs " + brief(b) + ")";
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (std::string d = first_difference(a[i], b[i], path + "[" + std::to_string(i) + "]"); !d.empty()) return d;
    }
    return "";
  }
  return a == b ? "" : path + ": " + brief(a) + " vs " + brief(b);
}

void check_same_suite(const ResultView& base, const ResultView& next) {
  // The path is where the file happened to live on each machine; everything else describes what was run.
  ojson a = base.suite, b = next.suite;
  a.erase("path");
  b.erase("path");
  std::string difference = first_difference(a, b, "suite");
  if (difference.empty()) {
    const auto seed = [](const ResultView& r) { return r.context.contains("seed") ? r.context["seed"] : ojson(); };
    if (seed(base) != seed(next)) difference = "context.seed: " + brief(seed(base)) + " vs " + brief(seed(next));
  }
  if (!difference.empty()) {
    throw SuiteMismatch(base.file + " and " + next.file + " are runs of different suites or settings (" +
                        difference + "); compare runs of the same suite and settings, or refresh the baseline "
                        "(scripts/refresh-baseline.sh)");
  }
}

std::string text(const std::optional<double>& v) {
  if (!v) return "null";
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, *v);
  return ec == std::errc() ? std::string(buf, end) : "?";
}

std::string status_text(const RepetitionView& r) {
  return r.diverged_step ? r.status + " at step " + std::to_string(*r.diverged_step) : r.status;
}

class ChangeList {
 public:
  explicit ChangeList(std::vector<BehaviourChange>& out) : out_(out) {}
  void check(const std::string& label, const char* metric, std::optional<int> rep, const std::string& a,
             const std::string& b) {
    if (a != b) out_.push_back({label, metric, rep, a, b});
  }

 private:
  std::vector<BehaviourChange>& out_;
};

void compare_repetitions(const CaseView& a, const CaseView& b, ChangeList& changes, std::size_t& compared) {
  std::map<int, const RepetitionView*> next;
  for (const RepetitionView& r : b.repetitions) next[r.repetition] = &r;
  changes.check(a.label, "repetitions", std::nullopt, std::to_string(a.repetitions.size()),
                std::to_string(b.repetitions.size()));
  for (const RepetitionView& ra : a.repetitions) {
    const auto it = next.find(ra.repetition);
    if (it == next.end()) continue;  // already reported through the count
    const RepetitionView& rb = *it->second;
    ++compared;
    const int rep = ra.repetition;
    changes.check(a.label, "status", rep, status_text(ra), status_text(rb));
    changes.check(a.label, "N", rep, text(ra.mean_nodes), text(rb.mean_nodes));
    changes.check(a.label, "L", rep, text(ra.mean_links), text(rb.mean_links));
    changes.check(a.label, "I", rep, text(ra.mean_interpolations), text(rb.mean_interpolations));
    changes.check(a.label, "operations", rep, std::to_string(ra.operations), std::to_string(rb.operations));
    changes.check(a.label, "final_state_hash", rep, ra.final_state_hash, rb.final_state_hash);
  }
}

std::string joined_labels(const ResultView& r) {
  std::string out;
  for (const CaseView& c : r.cases) out += (out.empty() ? "" : ",") + c.label;
  return shorten(out);
}

bool has_time_budget(const ResultView& r) {
  const auto feedback = r.suite.find("feedback");
  if (feedback == r.suite.end() || !feedback->is_object()) return false;
  const auto budget = feedback->find("max_step_ms");
  return budget != feedback->end() && budget->is_number() && budget->get<double>() > 0.0;
}

std::vector<std::string> machine_differences(const ResultView& base, const ResultView& next) {
  // What makes absolute times incomparable; the host name and date differ between any two runs and say nothing.
  // Huge pages change large nets' step and operation times by 10-17 % (docs/methodology.md, "Huge pages").
  static const char* const kMachineKeys[] = {
      "cpu_model", "cores",          "compiler",         "cxx_flags",             "build_type",    "optimized",
      "sanitized", "bullet_version", "bullet_precision", "transparent_hugepages", "glibc_tunables"};
  std::vector<std::string> out;
  for (const char* key : kMachineKeys) {
    const ojson a = base.context.contains(key) ? base.context[key] : ojson();
    const ojson b = next.context.contains(key) ? next.context[key] : ojson();
    if (a != b) out.push_back(std::string(key) + ": " + brief(a) + " vs " + brief(b));
  }
  return out;
}

}  // namespace

ResultComparison compare_results(const ResultView& base, const ResultView& next) {
  check_same_suite(base, next);
  ResultComparison out;
  const auto name = base.suite.find("name");
  const auto sha = base.suite.find("sha256");
  out.suite_name = name != base.suite.end() && name->is_string() ? name->get<std::string>() : "";
  out.suite_sha256 = sha != base.suite.end() && sha->is_string() ? sha->get<std::string>() : "";
  out.deterministic = !has_time_budget(base);
  out.machine_differences = machine_differences(base, next);

  std::map<std::string, std::size_t> next_index;
  for (std::size_t i = 0; i < next.cases.size(); ++i) next_index.emplace(next.cases[i].label, i);
  ChangeList changes(out.changes);
  changes.check("", "cases", std::nullopt, joined_labels(base), joined_labels(next));

  for (std::size_t i = 0; i < base.cases.size(); ++i) {
    const CaseView& a = base.cases[i];
    const auto it = next_index.find(a.label);
    if (it == next_index.end()) continue;
    const std::size_t j = it->second;
    const CaseView& b = next.cases[j];
    ++out.cases;
    if (out.deterministic) {
      changes.check(a.label, "status", std::nullopt, a.status, b.status);
      changes.check(a.label, "N", std::nullopt, text(a.mean_nodes), text(b.mean_nodes));
      changes.check(a.label, "L", std::nullopt, text(a.mean_links), text(b.mean_links));
      changes.check(a.label, "I", std::nullopt, text(a.mean_interpolations), text(b.mean_interpolations));
      compare_repetitions(a, b, changes, out.repetitions);
    } else {
      out.repetitions += std::min(a.repetitions.size(), b.repetitions.size());
    }

    out.step_ms.push_back({a.label, kStepMsMetric, {ok_step_times(a), ok_step_times(b)}});
    if (a.method != "tcsb") continue;
    const auto plain_a = plain_case_of(base, i);
    const auto plain_b = plain_case_of(next, j);
    if (!plain_a || !plain_b) continue;
    out.ratios.push_back(
        {a.label, kRatioMetric, {paired_step_ratios(base, i, *plain_a), paired_step_ratios(next, j, *plain_b)}});
  }
  return out;
}

}  // namespace tcsb
