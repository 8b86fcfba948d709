#include "sweep/shard_merge.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>

#include "base/json_fields.h"
#include "gate/result_comparison.h"
#include "report/json_report.h"
#include "report/shard_section.h"
#include "run/case_summary.h"
#include "suite/fidelity_plan.h"
#include "sweep/shard_plan.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// The context fields that make two shards different builds: their cases would not be one program's measurements.
constexpr const char* kBuildKeys[] = {"git_commit", "tcsb_version", "compiler",       "cxx_flags",
                                      "build_type", "sanitized",    "bullet_version", "bullet_precision"};

/// The context fields that tell machines apart for absolute times (what `tcsb compare` warns about, and the host).
constexpr const char* kMachineKeys[] = {"host", "cpu_model", "cores", "transparent_hugepages", "glibc_tunables"};

/// Typed reading of one shard document; every failure names the file and the field (base/json_fields.h).
using Reader = JsonFields<ojson>;

constexpr NumberRange kNonNegative{0.0, false};

/// A measured value as RunResult holds it: NaN where the file has null (nothing was measured), so writing the
/// merged run gives null again.
double measured(std::optional<double> value) { return value.value_or(std::numeric_limits<double>::quiet_NaN()); }

/// A shard's index from context.shard.
ShardIndex shard_index_of(const ShardDocument& shard) {
  const Reader r(shard.file);
  const ojson& context = r.member(shard.document, "", "context");
  if (!context.contains("shard")) {
    r.fail("context.shard", "missing: not a shard's result (write shards with `tcsb run SUITE --shard K/N`)");
  }
  const ojson& s = context["shard"];
  const std::int64_t k = r.integer(s, "context.shard", "k"), n = r.integer(s, "context.shard", "n");
  if (n < 1 || n > kMaxShards || k < 1 || k > n) {
    r.fail("context.shard", "k " + std::to_string(k) + " of n " + std::to_string(n) + " is not a shard index");
  }
  // Shards written before the split by repetition have no `split`: they split by net.
  ShardSplit split = ShardSplit::kNets;
  if (s.contains("split")) {
    const std::string name = r.string(s, "context.shard", "split");
    const std::optional<ShardSplit> parsed = parse_split(name);
    if (!parsed) r.fail("context.shard.split", "\"" + name + "\" is neither repetitions nor nets");
    split = *parsed;
  }
  return {static_cast<int>(k), static_cast<int>(n), split};
}

/// The suite the shards ran: the file's text from merge_data, with the effective settings of the result's suite
/// block (a run may narrow the methods and override compression, repetitions and the time budget), checked to
/// render exactly as that block.
Suite rebuild_suite(const ShardDocument& shard) {
  const Reader r(shard.file);
  const ojson& doc = shard.document;
  const std::string text = r.string(r.member(doc, "", "merge_data"), "merge_data", "suite_file");
  const ojson& block = r.member(doc, "", "suite");
  // Parsed as the file it was, where it was: its calibration (fidelity.calibration, relative to the suite) lies
  // beside the suite, not beside the shard, where a stale file of that name would be taken for it.
  const std::string suite_path = r.string(block, "suite", "path");
  // The effective settings, read before the suite text is parsed, so an InputError of the parse below is the
  // suite file's alone.
  std::vector<Method> methods;
  for (const ojson& m : r.array(block, "suite", "methods")) {
    const std::string name = m.is_string() ? m.get<std::string>() : "";
    const auto* it =
        std::find_if(std::begin(kAllMethods), std::end(kAllMethods), [&](Method k) { return name == method_name(k); });
    if (it == std::end(kAllMethods)) r.fail("suite.methods", "unknown method " + m.dump());
    methods.push_back(*it);
  }
  std::vector<double> compression;
  for (const ojson& c : r.array(block, "suite", "compression"))
    compression.push_back(c.is_number() ? c.get<double>() : 0);
  const auto repetitions = static_cast<int>(r.integer(block, "suite", "repetitions"));
  const double max_step_ms =
      measured(r.number_or_null(r.member(block, "suite", "feedback"), "suite.feedback", "max_step_ms"));
  Suite suite;
  try {
    suite = parse_suite_text(text, suite_path, [&](Suite& s) {
      s.methods = methods;
      s.compression = compression;
      s.repetitions = repetitions;
      s.feedback.max_step_ms = max_step_ms;
      // Merging runs nothing: no memory check for the suite's nets here.
      s.run_units.assign(configuration_count(s) * s.nets.size(), false);
    });
  } catch (const InputError& e) {
    throw InputError(shard.file, "merge_data.suite_file", e.what());
  }
  suite.run_units.clear();
  suite.path = suite_path;
  if (const std::string d = first_json_difference(suite_json(suite), block, "suite"); !d.empty()) {
    r.fail("suite", "does not match the suite file in merge_data.suite_file (" + d + ")");
  }
  return suite;
}

/// A repetition as the result records it (the per-step series are not in the file and no table reads them).
RepetitionResult read_repetition(const Reader& r, const ojson& j, const std::string& path) {
  RepetitionResult rep;
  rep.repetition = static_cast<int>(r.integer(j, path, "repetition"));
  rep.status = r.string(j, path, "status");
  rep.diverged_step = r.integer_or_null(j, path, "diverged_step");
  rep.diverged_reason = r.string(j, path, "diverged_reason");
  rep.mean_step_ms = measured(r.non_negative_or_null(j, path, "mean_step_ms"));
  rep.median_step_ms = measured(r.non_negative_or_null(j, path, "median_step_ms"));
  rep.mean_nodes = measured(r.non_negative_or_null(j, path, "mean_nodes"));
  rep.mean_links = measured(r.non_negative_or_null(j, path, "mean_links"));
  rep.mean_interpolations = measured(r.non_negative_or_null(j, path, "mean_interpolations"));
  rep.mean_feedback_ms = measured(r.non_negative_or_null(j, path, "mean_feedback_ms"));
  rep.mean_feedback_total_ms = measured(r.non_negative_or_null(j, path, "mean_feedback_total_ms"));
  rep.operations = r.integer(j, path, "operations");
  rep.final_state_hash = r.string(j, path, "final_state_hash");
  rep.build_ms = measured(r.non_negative_or_null(j, path, "build_ms"));
  return rep;
}

/// A TC-SB case's operation samples from merge_data.op_samples, column by column.
std::vector<OpSample> read_op_samples(const Reader& r, const ojson& data, const std::string& label) {
  const std::string path = "merge_data.op_samples." + label;
  const ojson& columns = r.member(r.member(data, "merge_data", "op_samples"), "merge_data.op_samples", label);
  const ojson& work = r.member(columns, path, "work");
  std::vector<const ojson*> all;
  for (const char* c : kMergeSampleColumns) all.push_back(&r.member(columns, path, c));
  for (int w = 0; w < kOpWorkCountKinds; ++w)
    all.push_back(&r.member(work, path + ".work", op_work_count_name(OpWorkCount(w))));
  const std::size_t size = all.front()->is_array() ? all.front()->size() : 0;
  for (const ojson* column : all) {
    if (!column->is_array() || column->size() != size) r.fail(path, "columns must be arrays of one length");
    // Times and counts: a sample of -1 ns would become a negative operation time in Table 1.
    for (const ojson& v : *column) r.integer(v, path, 0, INT32_MAX);
  }
  const auto value = [&](std::size_t column, std::size_t i) { return (*all[column])[i].get<std::int32_t>(); };
  std::vector<OpSample> samples(size);
  for (std::size_t i = 0; i < size; ++i) {
    const std::int32_t kind = value(0, i);
    if (kind < 0 || kind >= kOpKindCount) r.fail(path + ".kind", "must be 0 to " + std::to_string(kOpKindCount - 1));
    OpWork w;
    std::int32_t* counts[] = {
        &w.nodes,         &w.links, &w.tree_records, &w.dbvt_leaves, &w.relocation_nodes, &w.relocation_links,
        &w.dbvt_ancestors};
    for (int c = 0; c < kOpWorkCountKinds; ++c) *counts[c] = value(6 + static_cast<std::size_t>(c), i);
    w.interior = value(5, i) != 0;
    samples[i] = OpSample(static_cast<OpKind>(kind), value(1, i), value(2, i), value(3, i), value(4, i), w);
  }
  return samples;
}

/// A metric summary (mean, p95, max) at `path`.`key` as the writer records it.
MetricSummary read_metric(const Reader& r, const ojson& j, const std::string& path, const char* key) {
  MetricSummary m;
  const ojson& s = r.member(j, path, key);
  const std::string sub = path + "." + key;
  if (r.member(s, sub, "mean").is_null()) return m;  // never measured: count 0, as the writer's null says
  m.count = 1;  // the file does not keep the step count; the tables only ask whether there is one
  m.mean = measured(r.number_or_null(s, sub, "mean"));
  m.p95 = measured(r.number_or_null(s, sub, "p95"));
  m.max = measured(r.number_or_null(s, sub, "max"));
  return m;
}

/// Screen metrics (a case's "screen", a floor's "noise_floor_screen") at `path`.
ScreenMetrics read_screen(const Reader& r, const ojson& j, const std::string& path) {
  ScreenMetrics s;
  s.mean_px = read_metric(r, j, path, "mean_px");
  s.p95_px = read_metric(r, j, path, "p95_px");
  s.max_px = read_metric(r, j, path, "max_px");
  s.p95_over_1px_share = measured(r.number_or_null(j, path, "p95_over_1px_share"));
  s.points_in_view = measured(r.number_or_null(j, path, "points_in_view"));
  return s;
}

/// The optional array of non-negative numbers `key` (block times; results written before them lack it: empty).
std::vector<double> read_optional_numbers(const Reader& r, const ojson& j, const std::string& path, const char* key) {
  std::vector<double> out;
  if (const ojson* list = r.find(j, path, key)) {
    const std::string at = path + "." + key;
    r.array(*list, at, EmptyArray::kAllowed);
    for (std::size_t k = 0; k < list->size(); ++k)
      out.push_back(r.number((*list)[k], at + "[" + std::to_string(k) + "]", kNonNegative));
  }
  return out;
}

/// A fidelity case of net `net`, subject `subject`, as the shard's fidelity section records it.
FidelityCase read_fidelity_case(const Reader& r, const ojson& j, const std::string& path, std::size_t net,
                                const FidelitySubjectSpec& subject) {
  FidelityCase c;
  c.net = net;
  c.net_name = r.string(j, path, "net");
  c.subject = subject;
  if (r.string(j, path, "method") != subject.method) {
    r.fail(path + ".method", "expected " + subject.method + " here");
  }
  c.target_nodes = static_cast<int>(r.integer(j, path, "target_nodes"));
  c.mean_nodes = measured(r.number_or_null(j, path, "N"));
  const ojson& grid = r.member(j, path, "grid");
  c.grid = grid.is_string() ? grid.get<std::string>() : "";
  c.status = r.string(j, path, "status");
  c.diverged_step = r.integer_or_null(j, path, "diverged_step");
  c.diverged_reason = r.string(j, path, "diverged_reason");
  const auto metric = [&](const char* key) { return read_metric(r, j, path, key); };
  c.rms_pct = metric("rms_pct");
  c.max_pct = metric("max_pct");
  c.weighted_rms_pct = metric("weighted_rms_pct");
  c.popping_pct = metric("popping_pct");
  c.energy_drift_pct = metric("energy_drift_pct");
  c.step_ms = measured(r.number_or_null(j, path, "step_ms"));
  c.reference_step_ms = measured(r.number_or_null(j, path, "reference_step_ms"));
  c.block_step_ms = read_optional_numbers(r, j, path, "block_step_ms");
  c.switch_ms = r.number_or_null(j, path, "switch_ms");
  c.switch_step = r.integer_or_null(j, path, "switch_step");
  c.converged_step = r.integer_or_null(j, path, "converged_step");
  c.final_state_hash = r.string(j, path, "final_state_hash");
  if (j.contains("screen")) c.screen = read_screen(r, j["screen"], path + ".screen");
  return c;
}

/// A case as one shard measured it: its header and its repetitions (each with its operation samples), in the order
/// the shard ran them.
struct CasePiece {
  CaseResult header;  ///< key, label and net; no repetitions
  std::vector<RepetitionResult> repetitions;
  std::vector<std::vector<OpSample>> samples;  ///< per repetition
  /// Shards written before merge_data.breakdown_ms: the case's summary as the shard gave it (all its repetitions
  /// then ran in that one shard, split by net).
  std::optional<StepBreakdown> summary_breakdown;
};

/// What one shard contributes: its cases (by suite-wide case index) and fidelity cases (by net).
struct ShardPart {
  std::map<std::size_t, CasePiece> cases;
  std::map<std::size_t, std::vector<FidelityCase>> fidelity;
  std::map<std::size_t, FidelityFloors> floors;  ///< by net; none from a result that records no floors
  double fidelity_wall_s = 0;
};

/// "[0, 2, 4]".
std::string number_list(const std::vector<int>& numbers) {
  std::string text;
  for (const int n : numbers) text += (text.empty() ? "" : ", ") + std::to_string(n);
  return "[" + text + "]";
}

/// The per-repetition breakdowns of case `label` from merge_data.breakdown_ms, one per repetition.
std::vector<StepBreakdown> read_breakdowns(const Reader& r, const ojson& list, const std::string& label,
                                           std::size_t repetitions) {
  const std::string path = "merge_data.breakdown_ms." + label;
  if (!list.is_array() || list.size() != repetitions)
    r.fail(path, "must hold one breakdown per repetition (" + std::to_string(repetitions) + ")");
  std::vector<StepBreakdown> out;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const ojson& parts = list[k];
    const std::string at = path + "[" + std::to_string(k) + "]";
    if (!parts.is_array() || parts.size() != std::size(kMergeBreakdownParts)) r.fail(at, "must hold 4 numbers");
    double v[4];
    for (std::size_t i = 0; i < 4; ++i) v[i] = measured(r.number_or_null(parts[i], index_path(at, i), kNonNegative));
    out.push_back({v[0], v[1], v[2], v[3]});
  }
  return out;
}

/// A case's repetitions from every shard that measured some, in repetition order, summarised as the run does.
CaseResult join_pieces(std::vector<CasePiece>& pieces) {
  CaseResult c = pieces.front().header;
  std::vector<std::pair<RepetitionResult*, std::vector<OpSample>*>> all;
  for (CasePiece& p : pieces)
    for (std::size_t k = 0; k < p.repetitions.size(); ++k) all.push_back({&p.repetitions[k], &p.samples[k]});
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return a.first->repetition < b.first->repetition; });
  for (auto& [rep, samples] : all) {
    c.repetitions.push_back(std::move(*rep));
    c.ops.samples.insert(c.ops.samples.end(), samples->begin(), samples->end());
  }
  summarize_case(c);  // the run's own summary of the repetitions, so the merged case is the unsharded one
  if (pieces.size() == 1 && pieces.front().summary_breakdown) c.breakdown = *pieces.front().summary_breakdown;
  return c;
}

/// A summary as the fidelity JSON records it: its mean alone (null when never measured). Every table reads only
/// the mean (summary_mean), so the merged run's tables and JSON are the unsharded run's.
MetricSummary summary_of_mean(double mean) {
  MetricSummary s;
  if (!std::isnan(mean)) {
    s.count = 1;
    s.mean = s.p95 = s.max = mean;
  }
  return s;
}

/// The floors of net `net` as the shard's `fidelity.floors[k]` records them.
FidelityFloors read_floors(const Reader& r, const ojson& j, const std::string& path, std::size_t net,
                           const std::string& net_name) {
  FidelityFloors f;
  f.net = net;
  f.net_name = r.string(j, path, "net");
  if (f.net_name != net_name) r.fail(path + ".net", "expected " + net_name + " here");
  f.noise_rms_pct = summary_of_mean(measured(r.number_or_null(j, path, "noise_floor_pct")));
  if (j.contains("noise_floor_screen"))
    f.noise_screen = read_screen(r, j["noise_floor_screen"], path + ".noise_floor_screen");
  f.reference_block_step_ms = read_optional_numbers(r, j, path, "reference_block_step_ms");
  const ojson& list = r.member(j, path, "interpolation_floor_pct");
  if (!list.is_array()) r.fail(path + ".interpolation_floor_pct", "must be an array");
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string at = path + ".interpolation_floor_pct[" + std::to_string(k) + "]";
    f.interpolation.push_back({.compression = measured(r.number_or_null(list[k], at, "compression")),
                               .grid = r.string(list[k], at, "grid"),
                               .rms_pct = summary_of_mean(measured(r.number_or_null(list[k], at, "rms_pct")))});
  }
  if (const ojson* reference = r.find(j, path, "reference")) {  // the compliant material's converged reference
    const std::string at = path + ".reference";
    ReferenceSubsteps& out = f.reference.emplace();
    out.substeps = static_cast<int>(r.integer(*reference, at, "substeps", 1, INT_MAX));
    out.converged = r.boolean(r.member(*reference, at, "converged"), at + ".converged");
    const ojson& doublings = r.array(*reference, at, "doublings");
    for (std::size_t k = 0; k < doublings.size(); ++k) {
      const std::string d = at + ".doublings[" + std::to_string(k) + "]";
      out.doublings.push_back({.substeps = static_cast<int>(r.integer(doublings[k], d, "substeps", 1, INT_MAX)),
                               .change_rms_pct = measured(r.number_or_null(doublings[k], d, "change_rms_pct")),
                               .noise_rms_pct = measured(r.number_or_null(doublings[k], d, "noise_rms_pct")),
                               .diverged = r.boolean(r.member(doublings[k], d, "diverged"), d + ".diverged")});
    }
  }
  return f;
}

/// Reads the cases of `shard`, which must be exactly those its index assigns, in the unsharded order, each with
/// exactly the repetitions its index assigns.
ShardPart read_shard(const ShardDocument& shard, const Suite& suite, const ShardIndex& index) {
  const Reader r(shard.file);
  const ojson& doc = shard.document;
  Suite mine = suite;
  restrict_to_shard(mine, index);
  const std::vector<CaseKey> keys = expand_cases(suite);
  std::vector<std::size_t> expected;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (runs_unit(mine, keys[i].configuration, keys[i].net)) expected.push_back(i);
  const ojson& cases = r.member(doc, "", "cases");
  if (!cases.is_array() || cases.size() != expected.size()) {
    r.fail("cases", std::to_string(cases.is_array() ? cases.size() : 0) + " cases, but shard " + shard_text(index) +
                        " (split by " + split_name(index.split) + ") of suite " + suite.name + " has " +
                        std::to_string(expected.size()));
  }
  const ojson& merge_data = r.member(doc, "", "merge_data");
  const ojson* breakdowns = merge_data.contains("breakdown_ms") ? &merge_data["breakdown_ms"] : nullptr;
  if (index.split == ShardSplit::kRepetitions && !breakdowns) r.fail("merge_data.breakdown_ms", "missing");
  ShardPart part;
  for (std::size_t e = 0; e < expected.size(); ++e) {
    const std::size_t index_in_suite = expected[e];
    const std::string path = "cases[" + std::to_string(e) + "]";
    const ojson& j = cases[e];
    CasePiece piece;
    CaseResult& c = piece.header;
    c.key = keys[index_in_suite];
    c.label = r.string(j, path, "label");
    if (c.label != case_label(suite, c.key)) {
      r.fail(path + ".label",
             "\"" + c.label + "\", but shard " + shard_text(index) + " has \"" + case_label(suite, c.key) + "\" here");
    }
    c.net_name = r.string(j, path, "net");
    c.net_nodes = r.integer(j, path, "net_nodes");
    c.net_links = r.integer(j, path, "net_links");
    c.target_nodes = static_cast<int>(r.integer(j, path, "target_nodes"));
    // The repetitions its index assigns, no other, none twice, in order: a repetition missing from the merge or in
    // it twice would change every summary without a trace.
    std::vector<int> assigned, found;
    for (int rep = 0; rep < suite.repetitions; ++rep)
      if (runs_repetition(mine, c.key.configuration, c.key.net, rep)) assigned.push_back(rep);
    const ojson& reps = r.member(j, path, "repetitions");
    for (std::size_t k = 0; k < reps.size(); ++k) {
      piece.repetitions.push_back(read_repetition(r, reps[k], path + ".repetitions[" + std::to_string(k) + "]"));
      piece.repetitions.back().process = index.k;
      found.push_back(piece.repetitions.back().repetition);
    }
    if (found != assigned) {
      r.fail(path + ".repetitions", "repetitions " + number_list(found) + ", but shard " + shard_text(index) +
                                        " (split by " + split_name(index.split) + ") has " + number_list(assigned));
    }
    std::vector<OpSample> samples;
    if (c.key.method == Method::kTcsb) samples = read_op_samples(r, merge_data, c.label);
    std::size_t offset = 0;
    for (const RepetitionResult& rep : piece.repetitions) {
      const auto count = static_cast<std::size_t>(std::max<std::int64_t>(rep.operations, 0));
      if (c.key.method == Method::kTcsb && offset + count > samples.size())
        r.fail("merge_data.op_samples." + c.label, "fewer samples than the repetitions' operations");
      const auto first = samples.begin() + static_cast<std::ptrdiff_t>(std::min(offset, samples.size()));
      piece.samples.emplace_back(
          first, first + static_cast<std::ptrdiff_t>(c.key.method == Method::kTcsb ? count : std::size_t{0}));
      offset += count;
    }
    if (c.key.method == Method::kTcsb && offset != samples.size())
      r.fail("merge_data.op_samples." + c.label, "more samples than the repetitions' operations");
    if (breakdowns) {
      const std::vector<StepBreakdown> parts = read_breakdowns(
          r, r.member(*breakdowns, "merge_data.breakdown_ms", c.label), c.label, piece.repetitions.size());
      for (std::size_t k = 0; k < parts.size(); ++k) piece.repetitions[k].breakdown = parts[k];
    } else if (const auto b = j.find("step_breakdown_ms"); b != j.end()) {
      // An older shard, split by net: the case's summary as the shard gave it (all its repetitions ran there).
      const std::string at = path + ".step_breakdown_ms";
      piece.summary_breakdown =
          StepBreakdown{measured(r.number_or_null(*b, at, "bullet")), measured(r.number_or_null(*b, at, "feedback")),
                        measured(r.number_or_null(*b, at, "operations")),
                        measured(r.number_or_null(*b, at, "blending"))};
    }
    part.cases.emplace(index_in_suite, std::move(piece));
  }
  // The fidelity pass (never with axes: one configuration) is per net, in the shard of the net's first repetition.
  std::vector<bool> nets(suite.nets.size());
  for (std::size_t net = 0; net < nets.size(); ++net) nets[net] = runs_fidelity_of(mine, net);
  const std::vector<FidelitySubjectSpec> plan = fidelity_plan(suite);
  if (plan.empty()) return part;
  const ojson& fidelity = r.member(doc, "", "fidelity");
  const ojson& fcases = r.member(fidelity, "fidelity", "cases");
  std::size_t next = 0;
  for (std::size_t net = 0; net < suite.nets.size(); ++net) {
    if (!nets[net]) continue;
    for (const FidelitySubjectSpec& subject : plan) {
      const std::string path = "fidelity.cases[" + std::to_string(next) + "]";
      if (next >= fcases.size()) r.fail(path, "missing (net " + suite.nets[net].name + ")");
      part.fidelity[net].push_back(read_fidelity_case(r, fcases[next], path, net, subject));
      ++next;
    }
  }
  if (next != fcases.size()) r.fail("fidelity.cases", "more cases than shard " + shard_text(index) + " runs");
  if (fidelity.contains("floors")) {  // optional: results from before the floors have none
    const ojson& floors = fidelity["floors"];
    if (!floors.is_array()) r.fail("fidelity.floors", "must be an array");
    std::size_t k = 0;
    for (std::size_t net = 0; net < suite.nets.size(); ++net) {
      if (!nets[net]) continue;
      const std::string path = "fidelity.floors[" + std::to_string(k) + "]";
      if (k >= floors.size()) r.fail(path, "missing (net " + suite.nets[net].name + ")");
      part.floors.emplace(net, read_floors(r, floors[k], path, net, suite.nets[net].name));
      ++k;
    }
    if (k != floors.size()) r.fail("fidelity.floors", "more nets than shard " + shard_text(index) + " runs");
  }
  part.fidelity_wall_s = measured(r.non_negative_or_null(fidelity, "fidelity", "wall_s"));
  return part;
}

/// Fails naming `shard` when its `key` in `block` differs from the first shard's.
void check_same(const ShardDocument& first, const ShardDocument& shard, const char* block, const char* key,
                const char* what) {
  const ojson& a = first.document[block];
  const ojson& b = shard.document[block];
  const ojson va = a.contains(key) ? a[key] : ojson(), vb = b.contains(key) ? b[key] : ojson();
  if (va != vb) {
    throw InputError(shard.file, std::string(block) + "." + key,
                     vb.dump() + ", but " + first.file + " has " + va.dump() + ": " + what);
  }
}

}  // namespace

MergedShards merge_shards(const std::vector<ShardDocument>& shards) {
  if (shards.empty()) throw InputError("tcsb merge", "", "no shard results given");
  std::vector<ShardIndex> indices;
  for (const ShardDocument& s : shards) indices.push_back(shard_index_of(s));
  const ShardDocument& first = shards.front();
  const int n = indices.front().n;
  std::map<int, std::size_t> given;  // k -> position in `shards`
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const ShardDocument& s = shards[i];
    if (indices[i].split != indices.front().split) {
      throw InputError(s.file, "context.shard.split",
                       std::string("split by ") + split_name(indices[i].split) + ", but " + first.file +
                           " is split by " + split_name(indices.front().split) + ": not one split");
    }
    if (indices[i].n != n) {
      throw InputError(s.file, "context.shard",
                       "shard " + shard_text(indices[i]) + ", but " + first.file + " is a shard of " +
                           std::to_string(n) + ": not one split");
    }
    check_same(first, s, "context", "suite_sha256", "shards of different suite files");
    check_same(first, s, "suite", "name", "shards of different suites");
    check_same(first, s, "context", "seed", "shards of different seeds");
    for (const char* key : kBuildKeys) check_same(first, s, "context", key, "shards of different builds");
    ojson a = first.document["suite"], b = s.document["suite"];
    a.erase("path");
    b.erase("path");
    if (const std::string d = first_json_difference(b, a, "suite"); !d.empty()) {
      throw InputError(s.file, "suite", "settings differ from " + first.file + "'s (" + d + ")");
    }
    if (const auto [it, fresh] = given.emplace(indices[i].k, i); !fresh) {
      throw InputError(s.file, "context.shard",
                       "shard " + shard_text(indices[i]) + " given twice (also " + shards[it->second].file + ")");
    }
  }
  for (int k = 1; k <= n; ++k) {
    if (!given.contains(k)) {
      std::string files;
      for (const ShardDocument& s : shards) files += (files.empty() ? "" : ", ") + s.file;
      throw InputError(files, "context.shard", "shard " + shard_text({k, n}) + " is missing");
    }
  }

  MergedShards merged;
  RunResult& result = merged.result;
  result.suite = rebuild_suite(shards[given.at(1)]);
  std::map<std::size_t, std::vector<CasePiece>> cases;
  std::map<std::size_t, std::vector<FidelityCase>> fidelity;
  std::map<std::size_t, FidelityFloors> floors;
  double fidelity_wall_s = 0;
  for (const auto& [k, i] : given) {
    ShardPart part = read_shard(shards[i], result.suite, indices[i]);
    for (auto& [index, piece] : part.cases) cases[index].push_back(std::move(piece));
    fidelity.merge(part.fidelity);
    floors.merge(part.floors);
    fidelity_wall_s += part.fidelity_wall_s;
    // The sum of the shards' wall times: the machine time the suite took, wherever and however parallel it ran. A
    // run took a finite time of at least 0 s; anything else (negative, null for a non-finite one) would make the sum
    // a time no run took.
    const Reader r(shards[i].file);
    result.wall_s += r.number(r.member(shards[i].document, "", "wall_s"), "wall_s", NumberRange{0.0, false});
  }
  for (auto& [index, pieces] : cases) result.cases.push_back(join_pieces(pieces));
  if (!fidelity_plan(result.suite).empty()) {
    FidelityResult f;
    f.rms_threshold_pct = result.suite.fidelity.rms_threshold_pct;
    for (auto& [net, list] : fidelity)
      for (FidelityCase& c : list) f.cases.push_back(std::move(c));
    for (auto& [net, net_floors] : floors) f.floors.push_back(std::move(net_floors));
    f.wall_s = fidelity_wall_s;
    result.fidelity = std::move(f);
  }

  // The context: shard 1's, without its index, with every shard's warnings once and the merge's own.
  merged.context = shards[given.at(1)].document["context"];
  merged.context.erase("shard");
  std::vector<std::string> warnings;
  for (const auto& [k, i] : given) {
    const ojson& list = shards[i].document["context"]["warnings"];
    for (const ojson& w : list) {
      const std::string text = "shard " + std::to_string(k) + ": " + w.get<std::string>();
      warnings.push_back(text);
    }
  }
  std::set<std::string> machines;
  std::string machine_list;
  for (const auto& [k, i] : given) {
    ojson facts = ojson::object();
    for (const char* key : kMachineKeys) facts[key] = shards[i].document["context"].value(key, ojson());
    if (machines.insert(facts.dump()).second) {
      machine_list += (machine_list.empty() ? "" : "; ") + std::string("shard ") + std::to_string(k) + " on " +
                      facts["host"].dump() + " (" + facts["cpu_model"].dump() + ")";
    }
  }
  if (machines.size() > 1) {
    merged.warnings.push_back("shards ran on different machines (" + machine_list +
                              "): absolute step times mix machines; the same-run ratios stay valid, each measured "
                              "within one shard");
  }
  for (const std::string& w : merged.warnings) warnings.push_back(w);
  merged.context["warnings"] = warnings;
  merged.context["merged_shards"] = n;
  return merged;
}

ojson merged_json(const MergedShards& merged, const RunTables& tables) {
  ojson doc = native_json(merged.result, tables);
  doc["context"] = merged.context;
  return doc;
}

}  // namespace tcsb
