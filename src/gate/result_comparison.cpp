#include "gate/result_comparison.h"

#include <charconv>
#include <utility>

#include "gate/one_to_one_match.h"
#include "gate/run_consistency.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// At most 60 characters for a one-line message, "..." marking a cut.
std::string shorten(std::string text) { return text.size() > 60 ? text.substr(0, 57) + "..." : text; }

/// A JSON value for a one-line message: short, never multi-line.
std::string brief(const ojson& j) { return shorten(j.dump(-1, ' ', false, ojson::error_handler_t::replace)); }

void check_same_suite(const ResultView& base, const ResultView& next) {
  if (base.measure != next.measure) {
    throw SuiteMismatch(base.file + " measured " + base.measure + " and " + next.file + " measured " + next.measure +
                        ": a time result and an instruction count result cannot be compared");
  }
  if (const std::string difference = suite_difference(base, next, false); !difference.empty()) {
    throw SuiteMismatch(base.file + " and " + next.file + " are runs of different suites or settings (" + difference +
                        "); compare runs of the same suite and settings, or refresh the baseline "
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
  /// Records a change when the two values differ.
  void check(const std::string& label, const char* metric, std::optional<int> rep, const std::string& a,
             const std::string& b) {
    if (a != b) add(label, metric, rep, a, b);
  }
  /// Records a change whatever the values say ("2 entries" on both sides still cannot be matched).
  void add(const std::string& label, const char* metric, std::optional<int> rep, const std::string& a,
           const std::string& b) {
    out_.push_back({label, metric, rep, a, b});
  }

 private:
  std::vector<BehaviourChange>& out_;
};

/// A key's occurrences in one run, for a change row: a one-to-one match needs "present" on both sides.
std::string occurrence(std::size_t count) {
  if (count == 0) return "absent";
  if (count == 1) return "present";
  return std::to_string(count) + " entries";
}

/// Matches the repetitions of one case by number (never by position) and counts the matched ones in `compared`.
/// A missing, extra or duplicated number is changed behaviour in any run: which repetitions ran does not depend on
/// the machine. The values of a matched pair are compared only when the run is deterministic.
void compare_repetitions(const CaseView& a, const CaseView& b, bool deterministic, ChangeList& changes,
                         std::size_t& compared) {
  const auto numbers = [](const CaseView& c) {
    std::vector<int> out;
    for (const RepetitionView& r : c.repetitions) out.push_back(r.repetition);
    return out;
  };
  const std::vector<int> numbers_a = numbers(a), numbers_b = numbers(b);
  const OneToOneMatch<int> match = match_one_to_one<int>(numbers_a, numbers_b);
  for (const KeyOccurrences<int>& u : match.unmatched) {
    changes.add(a.label, kPresenceMetric, u.key, occurrence(u.base), occurrence(u.next));
  }
  compared += match.pairs.size();
  if (!deterministic) return;
  for (const auto& [i, j] : match.pairs) {
    const RepetitionView& ra = a.repetitions[i];
    const RepetitionView& rb = b.repetitions[j];
    const int rep = ra.repetition;
    changes.check(a.label, "status", rep, status_text(ra), status_text(rb));
    changes.check(a.label, "N", rep, text(ra.mean_nodes), text(rb.mean_nodes));
    changes.check(a.label, "L", rep, text(ra.mean_links), text(rb.mean_links));
    changes.check(a.label, "I", rep, text(ra.mean_interpolations), text(rb.mean_interpolations));
    changes.check(a.label, "operations", rep, std::to_string(ra.operations), std::to_string(rb.operations));
    changes.check(a.label, "final_state_hash", rep, ra.final_state_hash, rb.final_state_hash);
  }
}

std::vector<std::string> labels(const ResultView& r) {
  std::vector<std::string> out;
  for (const CaseView& c : r.cases) out.push_back(c.label);
  return out;
}

bool has_time_budget(const ResultView& r) {
  const auto feedback = r.suite.find("feedback");
  if (feedback == r.suite.end() || !feedback->is_object()) return false;
  const auto budget = feedback->find("max_step_ms");
  return budget != feedback->end() && budget->is_number() && budget->get<double>() > 0.0;
}

/// Cases pair by label, but the gate reads their other placing fields (a TC-SB case's plain partner is found by
/// net and configuration): a case whose net, method, compression or configuration differs from its baseline's under
/// the same label is not the case the baseline measured, and would leave a metric silently ungated.
void check_same_placement(const ResultView& base, std::size_t i, const ResultView& next, std::size_t j) {
  const CaseView &a = base.cases[i], &b = next.cases[j];
  const auto refuse = [&](const char* field, const std::string& va, const std::string& vb) {
    throw SuiteMismatch(next.file + ": cases[" + std::to_string(j) + "]." + field + ": " + vb + ", but " + base.file +
                        "'s case " + a.label + " has " + va +
                        " (a case's label, net, method, compression and configuration must agree)");
  };
  if (a.net != b.net) refuse("net", brief(a.net), brief(b.net));
  if (a.method != b.method) refuse("method", brief(a.method), brief(b.method));
  if (a.compression != b.compression) refuse("compression", text(a.compression), text(b.compression));
  if (a.configuration != b.configuration) refuse("configuration.label", brief(a.configuration), brief(b.configuration));
}

/// A metric's samples in both runs, each with the process that measured it (a merged result's shard).
TimingSamples timing_samples(MeasuredValues base, MeasuredValues next) {
  return {std::move(base.values), std::move(next.values), std::move(base.process), std::move(next.process)};
}

}  // namespace

std::vector<std::string> machine_differences(const ResultView& base, const ResultView& next) {
  // What makes absolute times incomparable; the host name and date differ between any two runs and say nothing.
  // Huge pages change large nets' step and operation times by 10-17 % (docs/methodology.md, "Huge pages").
  static const char* const kMachineKeys[] = {
      "cpu_model",     "cores",     "compiler",       "cxx_flags",        "build_type",
      "optimized",     "sanitized", "bullet_version", "bullet_precision", "transparent_hugepages",
      "glibc_tunables"};
  std::vector<std::string> out;
  for (const char* key : kMachineKeys) {
    const ojson a = base.context.contains(key) ? base.context[key] : ojson();
    const ojson b = next.context.contains(key) ? next.context[key] : ojson();
    if (a != b) out.push_back(std::string(key) + ": " + brief(a) + " vs " + brief(b));
  }
  return out;
}

std::string build_difference(const ResultView& a, const ResultView& b) {
  static const char* const kBuildKeys[] = {"git_commit", "tcsb_version",   "compiler",
                                           "cxx_flags",  "build_type",     "optimized",
                                           "sanitized",  "bullet_version", "bullet_precision"};
  for (const char* key : kBuildKeys) {
    const ojson va = a.context.contains(key) ? a.context[key] : ojson();
    const ojson vb = b.context.contains(key) ? b.context[key] : ojson();
    if (va != vb) return std::string("context.") + key + ": " + brief(va) + " vs " + brief(vb);
  }
  return "";
}

std::string suite_difference(const ResultView& a, const ResultView& b, bool ignore_repetitions) {
  // The path is where the file happened to live on each machine; everything else describes what was run.
  ojson sa = a.suite, sb = b.suite;
  for (ojson* suite : {&sa, &sb}) {
    suite->erase("path");
    if (ignore_repetitions) suite->erase("repetitions");
  }
  if (std::string difference = first_json_difference(sa, sb, "suite"); !difference.empty()) return difference;
  const auto seed = [](const ResultView& r) { return r.context.contains("seed") ? r.context["seed"] : ojson(); };
  if (seed(a) != seed(b)) return "context.seed: " + brief(seed(a)) + " vs " + brief(seed(b));
  return "";
}

std::string first_json_difference(const ojson& a, const ojson& b, const std::string& path) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      const std::string sub = path + "." + key;
      const auto it = b.find(key);
      if (it == b.end()) return sub + ": " + brief(value) + " vs absent";
      if (std::string d = first_json_difference(value, *it, sub); !d.empty()) return d;
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
      if (std::string d = first_json_difference(a[i], b[i], path + "[" + std::to_string(i) + "]"); !d.empty()) return d;
    }
    return "";
  }
  return a == b ? "" : path + ": " + brief(a) + " vs " + brief(b);
}

ResultComparison compare_results(const ResultView& base, const ResultView& next) {
  check_same_suite(base, next);
  // The instruction gate fails closed: a case without counts, or with counts no run writes, is refused, not skipped.
  check_instruction_counts(base);
  check_instruction_counts(next);
  ResultComparison out;
  out.measure = base.measure;
  const auto name = base.suite.find("name");
  const auto sha = base.suite.find("sha256");
  out.suite_name = name != base.suite.end() && name->is_string() ? name->get<std::string>() : "";
  out.suite_sha256 = sha != base.suite.end() && sha->is_string() ? sha->get<std::string>() : "";
  out.deterministic = !has_time_budget(base);
  out.machine_differences = machine_differences(base, next);

  // Cases pair by label, one to one: a case missing from either run, added, or listed twice is changed
  // behaviour (its row names the label), and is left out of the timings, which would otherwise pair the wrong data.
  ChangeList changes(out.changes);
  const std::vector<std::string> labels_a = labels(base), labels_b = labels(next);
  const OneToOneMatch<std::string> match = match_one_to_one<std::string>(labels_a, labels_b);
  for (const KeyOccurrences<std::string>& u : match.unmatched) {
    changes.add(u.key, kPresenceMetric, std::nullopt, occurrence(u.base), occurrence(u.next));
  }

  for (const auto& [i, j] : match.pairs) check_same_placement(base, i, next, j);
  for (const auto& [i, j] : match.pairs) {
    const CaseView& a = base.cases[i];
    const CaseView& b = next.cases[j];
    ++out.cases;
    if (out.deterministic) {
      changes.check(a.label, "status", std::nullopt, a.status, b.status);
      changes.check(a.label, "N", std::nullopt, text(a.mean_nodes), text(b.mean_nodes));
      changes.check(a.label, "L", std::nullopt, text(a.mean_links), text(b.mean_links));
      changes.check(a.label, "I", std::nullopt, text(a.mean_interpolations), text(b.mean_interpolations));
    }
    compare_repetitions(a, b, out.deterministic, changes, out.repetitions);

    out.step_ms.push_back({a.label, kStepMsMetric, timing_samples(ok_step_time_values(a), ok_step_time_values(b))});
    if (a.instructions && b.instructions) out.instructions.push_back({a.label, *a.instructions, *b.instructions});
    if (a.method != "tcsb") continue;
    const auto plain_a = plain_case_of(base, i);
    const auto plain_b = plain_case_of(next, j);
    if (!plain_a || !plain_b) continue;
    out.ratios.push_back(
        {a.label, kRatioMetric,
         timing_samples(paired_step_ratio_values(base, i, *plain_a), paired_step_ratio_values(next, j, *plain_b))});
  }
  return out;
}

}  // namespace tcsb
