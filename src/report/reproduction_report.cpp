#include "report/reproduction_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

#include "harness/claim_intervals.h"
#include "harness/fidelity_tables.h"
#include "harness/paper_claims.h"
#include "harness/paper_tables.h"
#include "harness/step_clock.h"
#include "report/claims_console.h"
#include "report/json_report.h"
#include "report/text_table.h"

namespace tcsb {

namespace {

using Align = TextTable::Align;

/// The paper's Table 2 label for one of our rows.
std::string paper_label(const Table2Row& row) { return row.method == "plain" ? "-" : row.compression_label; }

const PaperTable2Row* paper_row(const PaperReference& paper, const Table2Row& row) {
  if (row.method == "bullet_patch") return nullptr;
  const std::string method = row.method == "plain" ? "Bullet SoftBody" : "TC-SB";
  for (const PaperTable2Row& p : paper.table2)
    if (p.method == method && p.compression == paper_label(row)) return &p;
  return nullptr;
}

const PaperTable1Row* paper_row(const PaperReference& paper, const std::string& operation) {
  for (const PaperTable1Row& p : paper.table1)
    if (p.operation == operation) return &p;
  return nullptr;
}

nlohmann::ordered_json claim_json(const Claim& c) {
  const std::optional<bool> beyond_noise = decided(c);
  return {{"id", c.id},
          {"description", c.description},
          {"comparison", comparison_name(c.comparison)},
          {"expected", json_number(c.expected)},
          {"tolerance", json_number(c.tolerance)},
          {"measured", json_number(c.measured)},
          {"interval", c.interval ? nlohmann::ordered_json{{"low", json_number(c.interval->low)},
                                                            {"high", json_number(c.interval->high)}}
                                  : nlohmann::ordered_json(nullptr)},
          {"pass", c.pass},
          {"decided", beyond_noise ? nlohmann::ordered_json(*beyond_noise) : nlohmann::ordered_json(nullptr)}};
}

/// The fidelity row of TC-SB at a Table 2 row's target, when the run has a fidelity pass.
const FidelityRow* fidelity_row(const std::vector<FidelityRow>& rows, const Table2Row& row) {
  if (row.method != "tcsb" || !row.compression) return nullptr;
  for (const FidelityRow& f : rows)
    if (f.method == "tcsb" && same_compression(f.compression, *row.compression) && f.nets > 0) return &f;
  return nullptr;
}

std::vector<FidelityRow> fidelity_rows_of(const RunResult& result) {
  return result.fidelity ? fidelity_rows(*result.fidelity) : std::vector<FidelityRow>{};
}

}  // namespace

Reproduction check_reproduction(const RunResult& result, PaperReference paper) {
  Reproduction r;
  r.paper = std::move(paper);
  const std::vector<Table2Row> t2 = table2(result);
  r.claims = paper_claims(r.paper, t2, step_ms_vs_nodes(result), op_ms_vs_nodes(result));
  // How far each measured value could move had the run been repeated: the same claims recomputed on bootstrap
  // resamples of the repetitions. Seeded with the suite's seed, so the same measurements give the same intervals.
  const StepClock::time_point bootstrap0 = StepClock::now();
  const ClaimReplicates replicates = bootstrap_claims(
      result,
      [&](const RunResult& resample) {
        const std::vector<Table2Row> rt2 = table2(resample);
        std::vector<Claim> all = paper_claims(r.paper, rt2, step_ms_vs_nodes(resample), op_ms_vs_nodes(resample));
        // The wall-time target is not resampled: NaN leaves it without an interval.
        const std::vector<Claim> targets = project_targets(rt2, std::numeric_limits<double>::quiet_NaN());
        all.insert(all.end(), targets.begin(), targets.end());
        return all;
      },
      kClaimResamples, result.suite.seed);
  r.bootstrap_s = ms_between(bootstrap0, StepClock::now()) / 1000.0;
  r.wall_s = result.wall_s + r.bootstrap_s;
  r.targets = project_targets(t2, r.wall_s);
  attach_intervals(r.claims, replicates, kClaimConfidence);
  attach_intervals(r.targets, replicates, kClaimConfidence);
  if (result.fidelity) {  // reported beside the speed targets; like them, they do not gate the exit code
    const std::vector<Claim> fidelity = fidelity_targets(fidelity_rows(*result.fidelity));
    r.targets.insert(r.targets.end(), fidelity.begin(), fidelity.end());
  }
  return r;
}

nlohmann::ordered_json reproduction_json(const RunResult& result, const Reproduction& reproduction) {
  nlohmann::ordered_json t2 = nlohmann::ordered_json::array();
  const std::vector<FidelityRow> fidelity = fidelity_rows_of(result);
  for (const Table2Row& row : table2(result)) {
    const PaperTable2Row* p = paper_row(reproduction.paper, row);
    nlohmann::ordered_json paper = nullptr;
    if (p) paper = {{"N", p->N}, {"L", p->L}, {"I", p->I}, {"total_ms", p->total_ms},
                    {"time_ratio_vs_plain", json_number(reproduction.paper.time_ratio(p->compression))}};
    if (p && p->method != "TC-SB") paper["time_ratio_vs_plain"] = 1.0;
    t2.push_back({{"method", row.method},
                  {"compression", row.compression_label},
                  {"paper", paper},
                  {"ours", {{"N", json_number(row.N)}, {"L", json_number(row.L)}, {"I", json_number(row.I)},
                            {"total_ms", json_number(row.total_ms)},
                            {"time_ratio_vs_plain", json_number(row.time_ratio_vs_plain)},
                            {"node_ratio", json_number(row.node_ratio)}}}});
    // What the speed costs, from the fidelity pass (the `fidelity` section has every statistic).
    nlohmann::ordered_json error = nullptr;
    if (const FidelityRow* f = fidelity_row(fidelity, row))
      error = {{"rms_pct", json_number(f->rms_pct.mean)}, {"max_pct", json_number(f->max_pct.max)},
               {"weighted_rms_pct", json_number(f->weighted_rms_pct.mean)},
               {"popping_pct", json_number(f->popping_pct.max)},
               {"energy_drift_pct", json_number(f->energy_drift_pct.mean)}};
    t2.back()["ours"]["fidelity"] = error;
  }
  nlohmann::ordered_json t1 = nlohmann::ordered_json::array();
  for (const Table1Row& row : table1(result)) {
    const PaperTable1Row* p = paper_row(reproduction.paper, row.operation);
    nlohmann::ordered_json paper = nullptr;
    if (p) paper = {{"N", p->N}, {"L", p->L}, {"node_ops_ms", p->node_ops_ms}, {"link_ops_ms", p->link_ops_ms},
                    {"complete_ms", p->complete_ms}};
    const bool any = row.count > 0;
    const auto v = [&](double x) { return any ? json_number(x) : nlohmann::ordered_json(nullptr); };
    t1.push_back({{"operation", row.operation},
                  {"paper", paper},
                  {"ours", {{"N", v(row.N)}, {"L", v(row.L)}, {"node_ops_ms", v(row.node_ops_ms)},
                            {"link_ops_ms", v(row.link_ops_ms)}, {"complete_ms", v(row.complete_ms)},
                            {"p50_us", v(row.p50_us)}, {"p99_us", v(row.p99_us)}, {"count", row.count}}}});
  }
  nlohmann::ordered_json claims = nlohmann::ordered_json::array(), targets = nlohmann::ordered_json::array();
  for (const Claim& c : reproduction.claims) claims.push_back(claim_json(c));
  for (const Claim& c : reproduction.targets) targets.push_back(claim_json(c));
  return {{"paper_source", reproduction.paper.source},
          {"paper_hardware", reproduction.paper.hardware},
          {"table1", t1},
          {"table2", t2},
          {"claims", claims},
          {"targets", targets},
          {"pass", reproduction.pass()},
          {"bootstrap_s", json_number(reproduction.bootstrap_s)},
          {"wall_s", json_number(reproduction.wall_s)}};
}

void print_reproduction(const RunResult& result, const Reproduction& reproduction, std::ostream& out) {
  const std::vector<FidelityRow> fidelity = fidelity_rows_of(result);
  std::vector<TextTable::Column> columns{{"method", Align::kLeft}, {"compression", Align::kLeft}, {"paper N"},
                                         {"ours N"}, {"paper L"}, {"ours L"}, {"paper I"}, {"ours I"}, {"paper ms"},
                                         {"ours ms"}, {"paper ratio"}, {"ours ratio"}};
  if (result.fidelity) {  // the paper reports no error; ours, beside the speed it buys
    columns.push_back({"RMS %"});
    columns.push_back({"max %"});
    columns.push_back({"pop max %"});
  }
  TextTable t2(columns);
  for (const Table2Row& row : table2(result)) {
    const PaperTable2Row* p = paper_row(reproduction.paper, row);
    const auto pv = [&](double x) { return p ? std::optional(x) : std::nullopt; };
    std::optional<double> paper_ratio;
    if (p) paper_ratio = p->method == "TC-SB" ? reproduction.paper.time_ratio(p->compression) : 1.0;
    std::vector<std::string> cells{row.method, row.compression_label, fixed(pv(p ? p->N : 0), 0), fixed(row.N, 0),
                                   fixed(pv(p ? p->L : 0), 0), fixed(row.L, 0), fixed(pv(p ? p->I : 0), 1),
                                   fixed(row.I, 1), fixed(pv(p ? p->total_ms : 0), 2), general(row.total_ms, 4),
                                   fixed(paper_ratio, 3), fixed(row.time_ratio_vs_plain, 3)};
    if (const FidelityRow* f = fidelity_row(fidelity, row)) {
      cells.push_back(fixed(f->rms_pct.mean, 3));
      cells.push_back(fixed(f->max_pct.max, 3));
      cells.push_back(fixed(f->popping_pct.max, 3));
    }
    t2.add_row(std::move(cells));
  }
  out << "Table 2 beside the paper's (paper: " << reproduction.paper.hardware << "; ratios are to plain Bullet";
  if (result.fidelity)
    out << "; RMS: error against full-resolution plain Bullet in % of the net's extent, mean over steps and nets; "
           "max and pop: max over steps and nets";
  out << "):\n";
  t2.print(out);

  TextTable t1({{"operation", Align::kLeft}, {"paper N"}, {"ours N"}, {"paper us"}, {"ours us"}, {"ours p50 us"},
                {"ours p99 us"}, {"paper node %"}, {"ours node %"}, {"count"}});
  for (const Table1Row& row : table1(result)) {
    const PaperTable1Row* p = paper_row(reproduction.paper, row.operation);
    const auto pv = [&](double x) { return p ? std::optional(x) : std::nullopt; };
    const auto ov = [&](double x) { return row.count > 0 ? std::optional(x) : std::nullopt; };
    t1.add_row({row.operation, fixed(pv(p ? p->N : 0), 0), fixed(ov(row.N), 0),
                fixed(pv(p ? 1000 * p->complete_ms : 0), 2), fixed(ov(1000 * row.complete_ms), 2),
                fixed(ov(row.p50_us), 2), fixed(ov(row.p99_us), 2), fixed(pv(p ? p->node_ops_pct : 0), 1),
                fixed(ov(row.node_ops_pct), 1), std::to_string(row.count)});
  }
  out << "Table 1 beside the paper's (cost of one operation):\n";
  t1.print(out);
  print_claims("Claims of the paper (any FAIL: exit 1):", reproduction.claims, out);
  print_claims("Targets of this project (reported, not gating):", reproduction.targets, out);
  const bool intervals = std::any_of(reproduction.claims.begin(), reproduction.claims.end(),
                                     [](const Claim& c) { return c.interval.has_value(); });
  if (intervals)
    out << "95% interval: where the measured value could lie had the run been repeated (percentile bootstrap, "
        << kClaimResamples << " resamples of the repetitions, a net's cases drawn together so ratios stay paired; "
        << fixed(reproduction.bootstrap_s, 1) << " s). Beyond noise \"no\": the verdict flips inside the interval, "
        << "so this run cannot decide it.\n";
  else
    out << "No intervals: they need at least " << kMinRepetitionsForIntervals << " repetitions per case.\n";
  out << "Reproduction " << (reproduction.pass() ? "PASSED" : "FAILED") << " in " << fixed(reproduction.wall_s, 1)
      << " s\n";
}

}  // namespace tcsb
