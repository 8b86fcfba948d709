#include "report/comparison_summary.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "base/terminal_text.h"
#include "report/text_table.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

std::string or_dash(const std::optional<double>& v, const char* pattern) { return v ? formatted(pattern, *v) : "–"; }

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// Markdown table cells must not contain a bare '|'.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : terminal_safe(text)) {  // labels carry net names from the suite; the summary may go to stderr
    if (c == '|')
      out += "\\|";
    else if (c != '\n')
      out += c;
  }
  return out;
}

std::string context_string(const ResultView& r, const char* key) {
  const auto it = r.context.find(key);
  return it != r.context.end() && it->is_string() ? it->get<std::string>() : "unknown";
}

std::string describe_run(const ResultView& r) {
  std::string commit = context_string(r, "git_commit");
  if (commit.size() > 12) commit = commit.substr(0, 12) + (commit.ends_with("-dirty") ? "…-dirty" : "…");
  return "`" + r.file + "` (commit " + commit + ", " + context_string(r, "date_utc") + ", " +
         context_string(r, "cpu_model") + ", " + context_string(r, "build_type") + ")";
}

std::string verdict_cell(const TimingDecision& d, bool gated, std::size_t min_samples) {
  switch (d.verdict) {
    case TimingVerdict::kRegressed: return gated ? "**REGRESSED**" : "slower (warning only)";
    case TimingVerdict::kImproved: return "faster";
    case TimingVerdict::kUnchanged: return "ok";
    case TimingVerdict::kUndecided:
      if (!gated) return "undecided (not gated)";
      return d.more_repetitions ? "**undecided** (~" + std::to_string(*d.more_repetitions) + " more repetitions)"
                                : std::string("**undecided**");
    case TimingVerdict::kUnreliable: break;
  }
  if (!d.change) return "unreliable (no data)";
  return "unreliable (n < " + std::to_string(min_samples) + ")";
}

void timing_rows(std::ostream& out, const std::vector<TimingSeries>& series,
                 const std::vector<TimingDecision>& decisions, bool gated, std::size_t min_samples) {
  for (std::size_t i = 0; i < series.size() && i < decisions.size(); ++i) {
    const TimingDecision& d = decisions[i];
    std::string change = d.change ? formatted("%+.1f", 100.0 * *d.change) : "–";
    if (d.interval)
      change += formatted(" [%+.1f, ", 100.0 * d.interval->low) + formatted("%+.1f]", 100.0 * d.interval->high);
    if (d.interval && (d.base_processes > 1 || d.next_processes > 1))  // a merged result: its shards drawn first
      change += " (" + std::to_string(d.base_processes) + "/" + std::to_string(d.next_processes) + " processes)";
    out << "| " << cell(series[i].case_label) << " | " << series[i].metric << " | " << or_dash(d.base_median, "%.4g")
        << " | " << or_dash(d.next_median, "%.4g") << " | " << change << " | " << or_dash(d.p_value, "%.2g") << " | "
        << verdict_cell(d, gated, min_samples) << " |\n";
  }
}

void change_rows(std::ostream& out, const std::vector<BehaviourChange>& changes) {
  const std::size_t shown = std::min(changes.size(), kMaxChangeRows);
  for (std::size_t i = 0; i < shown; ++i) {
    const BehaviourChange& c = changes[i];
    std::string metric = c.metric;
    if (c.repetition) metric += " (rep " + std::to_string(*c.repetition) + ")";
    std::string change = "–";
    try {
      std::size_t used_a = 0, used_b = 0;
      const double a = std::stod(c.base, &used_a), b = std::stod(c.next, &used_b);
      if (used_a == c.base.size() && used_b == c.next.size() && a != 0.0)
        change = formatted("%+.2f", 100.0 * (b - a) / a);
    } catch (const std::exception&) {
      // Not numbers (a hash, a status): no percentage.
    }
    out << "| " << cell(c.case_label) << " | " << cell(metric) << " | " << cell(c.base) << " | " << cell(c.next)
        << " | " << change << " | – | **changed behaviour** |\n";
  }
  if (changes.size() > shown) {
    out << "\n…and " << plural(changes.size() - shown, "more behaviour change", "more behaviour changes")
        << " not shown.\n";
  }
}

std::string count_text(std::int64_t n) { return formatted("%.0f", static_cast<double>(n)); }

/// The instruction gate's rows: one per case (total, own, Bullet, change, verdict), and under each regressed case the
/// functions whose own instructions grew most.
void instruction_rows(std::ostream& out, const GateOutcome& o) {
  out << "| case | base instructions | new instructions | change % | TC-SB own (base → new) | Bullet (base → new) "
         "| verdict |\n";
  out << "|---|---:|---:|---:|---:|---:|---|\n";
  for (const InstructionDecision& d : o.instruction_decisions) {
    const std::string change = d.change ? formatted("%+.3f", 100.0 * *d.change) : "–";
    const char* verdict = d.regressed ? "**REGRESSED**" : d.improved ? "fewer" : "ok";
    out << "| " << cell(d.case_label) << " | " << count_text(d.base.total) << " | " << count_text(d.next.total) << " | "
        << change << " | " << count_text(d.base.own) << " → " << count_text(d.next.own) << " | "
        << count_text(d.base.bullet) << " → " << count_text(d.next.bullet) << " | " << verdict << " |\n";
  }
  for (const InstructionDecision& d : o.instruction_decisions) {
    if (d.shifts.empty()) continue;
    out << "\nWhere `" << terminal_safe(d.case_label) << "` grew (own instructions per function, largest increase "
        << "first):\n\n| function | base | new | change |\n|---|---:|---:|---:|\n";
    for (const FunctionShift& f : d.shifts) {
      out << "| " << cell(f.name) << " | " << (f.base > 0 || f.listed_in_both ? count_text(f.base) : "not listed")
          << " | " << count_text(f.next) << " | +" << count_text(f.next - f.base) << " |\n";
    }
  }
}

/// "PASS", "FAIL" or "UNDECIDED".
std::string verdict_word(const GateOutcome& o) {
  switch (o.verdict()) {
    case Verdict::kPass: return "PASS";
    case Verdict::kUndecided: return "UNDECIDED";
    case Verdict::kFail: break;
  }
  return "FAIL";
}

}  // namespace

std::string comparison_verdict_line(const GateOutcome& o) {
  const ResultComparison& c = o.comparison;
  std::string line = verdict_word(o) + ": ";
  if (o.counts) {
    return line + plural(o.regressions, "regression", "regressions") + ", " +
           plural(c.changes.size(), "behaviour change", "behaviour changes") + " (" +
           plural(o.gated_metrics, "case's instruction count", "cases' instruction counts") + " gated at threshold " +
           formatted("%g", 100.0 * o.settings.threshold) + " %" +
           (o.timings_decided() ? "" : "; counts undecided: " + undecided_reason(o)) + ")";
  }
  line += plural(o.regressions, "regression", "regressions") + ", " +
          plural(c.changes.size(), "behaviour change", "behaviour changes");
  if (o.undecided > 0) {
    line += ", " + std::to_string(o.undecided) + " undecided (about " +
            plural(static_cast<std::size_t>(o.more_repetitions()), "more repetition", "more repetitions") +
            " per run would likely decide)";
  }
  line += " (" + plural(o.gated_metrics, "timing metric", "timing metrics") + " gated at alpha " +
          formatted("%g", o.settings.alpha) + ", threshold " + formatted("%g", 100.0 * o.settings.threshold) + " %";
  if (const std::size_t unreliable = o.unreliable_metrics(); unreliable > 0) {
    line += "; " + std::to_string(unreliable) + " unreliable, not gated";
  }
  if (o.warnings > 0)
    line += "; " + plural(o.warnings, "absolute step time slower", "absolute step times slower") + ", not gated";
  if (!o.timings_decided()) line += "; timings undecided: " + undecided_reason(o);
  return line + ")";
}

std::string undecided_reason(const GateOutcome& o) {
  if (o.counts) return "no case has instruction counts in both runs";
  std::size_t family = o.ratio_decisions.size();
  std::size_t most = 0;  // the most samples any gated metric has on its smaller side
  const auto scan = [&](const std::vector<TimingDecision>& decisions) {
    for (const TimingDecision& d : decisions) most = std::max(most, std::min(d.base_count, d.next_count));
  };
  scan(o.ratio_decisions);
  if (o.absolute_gated) {
    family += o.step_decisions.size();
    scan(o.step_decisions);
  }
  if (family == 0) {
    return std::string("no timing metric to gate: no TC-SB case has a plain case on its net for `") + kRatioMetric +
           "`" + (o.absolute_gated ? "" : " (--absolute gates the step times too)");
  }
  std::string reason = "none of the " + plural(family, "gated timing metric", "gated timing metrics") +
                       " is reliable (each needs " + std::to_string(o.settings.min_samples) +
                       " ok repetitions on both sides; the most any has is " + std::to_string(most) + ")";
  if (most < o.settings.min_samples) {
    reason += ": rerun with suite.repetitions >= " + std::to_string(o.settings.min_samples);
  }
  return reason;
}

std::string comparison_summary_markdown(const GateOutcome& o, const ResultView& base, const ResultView& next) {
  const ResultComparison& c = o.comparison;
  std::ostringstream out;
  out << "## tcsb compare: " << verdict_word(o) << "\n\n";
  out << "- Base: " << describe_run(base) << "\n";
  out << "- New: " << describe_run(next) << "\n";
  out << "- Suite `" << terminal_safe(c.suite_name) << "` (sha256 `" << c.suite_sha256.substr(0, 12)
      << "…`): " << plural(c.cases, "case", "cases") << ", " << plural(c.repetitions, "repetition", "repetitions")
      << " compared.\n\n";
  out << "**" << plural(o.regressions, "regression", "regressions") << ", "
      << plural(c.changes.size(), "behaviour change", "behaviour changes");
  if (o.warnings > 0) out << ", " << plural(o.warnings, "warning", "warnings");
  out << ".**\n\n";

  if (o.counts) {
    out << "How: instructions counted by callgrind (`tcsb run --measure instructions`) over every timed step, TC-SB's "
           "own work and Bullet's step apart; a build counts the same in every run, so there is no noise to test "
           "against: a case whose total grows by more than "
        << formatted("%g", 100.0 * o.settings.threshold)
        << " % regressed. Every case and repetition must be present once in each run, and the deterministic metrics "
           "(N, L, I, operations, status, final-state hash) must match exactly. Step times under callgrind are not "
           "compared.\n\n";
    if (!c.changes.empty())
      out << "Behaviour changed (rows below). If that is intended, refresh the baseline in the same commit.\n\n";
    instruction_rows(out, o);
    if (!c.changes.empty()) {
      out << "\n| case | metric | base | new | change % | p-value | verdict |\n|---|---|---:|---:|---:|---:|---|\n";
      change_rows(out, c.changes);
    }
    return out.str();
  }
  out << "How: every case (by label) and repetition (by number) must be present once in each run, and their "
         "deterministic metrics (N, L, I, operations, status, final-state hash) must match exactly. Timing: a "
         "metric's change of the median gets a bootstrap interval (in brackets; each run's repetitions resampled, a "
         "merged run's processes first), each end a one-sided test at α / m = "
      << formatted("%g", o.settings.alpha) << " / " << o.gated_metrics << " over the gated metrics, and the threshold ("
      << formatted("%g", 100.0 * o.settings.threshold)
      << " %) is the margin: the whole interval above it is a regression, the whole interval at or below it is no "
         "regression, and an interval across it is undecided (exit 4), with about how many more repetitions per run "
         "would decide it. The p-value is the one-sided Mann–Whitney U test's, Holm-adjusted, for reference. With "
         "fewer than "
      << o.settings.min_samples
      << " repetitions on a side a metric is unreliable and never fails, and with no reliable gated metric the gate "
         "cannot pass. Gated: `"
      << kRatioMetric << "` (TC-SB step time / plain step time of the same net, per repetition, same run)"
      << (o.absolute_gated ? " and absolute `" + std::string(kStepMsMetric) + "`."
                           : "; absolute `" + std::string(kStepMsMetric) +
                                 "` is only reported (`--absolute` gates "
                                 "it).")
      << "\n\n";

  if (!c.deterministic) {
    out << "Deterministic metrics were not compared: `feedback.max_step_ms` > 0 lets step times steer the node "
           "budget, so N, L, I and the final state depend on the machine.\n\n";
  } else if (c.changes.empty()) {
    out << "Deterministic metrics: identical in " << plural(c.cases, "case", "cases") << " and "
        << plural(c.repetitions, "repetition", "repetitions") << ".\n\n";
  } else {
    out << "Behaviour changed (rows marked below). If that is intended, refresh the baseline in the same commit: "
           "`bash scripts/refresh-baseline.sh`.\n\n";
  }

  out << "| case | metric | base median | new median | change % | p-value | verdict |\n";
  out << "|---|---|---:|---:|---:|---:|---|\n";
  timing_rows(out, c.ratios, o.ratio_decisions, true, o.settings.min_samples);
  timing_rows(out, c.step_ms, o.step_decisions, o.absolute_gated, o.settings.min_samples);
  change_rows(out, c.changes);

  if (!c.machine_differences.empty()) {
    out << "\nThe runs come from different machines or builds, so absolute step times are not comparable:\n";
    for (const std::string& d : c.machine_differences) out << "- " << d << "\n";
  }
  return out.str();
}

}  // namespace tcsb
