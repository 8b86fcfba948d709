#include "report/reproduction_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

#include "paper/claim_intervals.h"
#include "report/claims_console.h"
#include "report/json_number.h"
#include "report/text_table.h"

namespace tcsb {

namespace {

using Align = TextTable::Align;

/// The paper's Table 2 label for one of our rows.
std::string paper_label(const Table2Row& row) { return row.method == "plain" ? "-" : row.compression_label; }

const PaperTable2Row* paper_row(const PaperReference& paper, const Table2Row& row) {
  // The paper ran neither CreatePatch nor a static body of TC-SB's node count.
  if (row.method != "plain" && row.method != "tcsb") return nullptr;
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

nlohmann::ordered_json claim_json(const TrackedClaim& t) {
  const Claim& c = t.claim;
  nlohmann::ordered_json interval = nullptr;
  if (c.interval)
    interval = {{"low", json_number(c.interval->low)},
                {"high", json_number(c.interval->high)},
                {"confidence", json_number(t.confidence)}};
  return {{"id", c.id},
          {"description", c.description},
          {"comparison", comparison_name(c.comparison)},
          {"expected", json_number(c.expected)},
          {"tolerance", json_number(c.tolerance)},
          {"evidence", evidence_name(c.evidence)},
          {"measured", json_number(c.measured)},
          {"interval", interval},
          {"verdict", verdict_name(verdict(c))},
          {"look", t.look > 0 ? nlohmann::ordered_json(t.look) : nlohmann::ordered_json(nullptr)},
          {"repetitions", t.look > 0 ? nlohmann::ordered_json(t.repetitions) : nlohmann::ordered_json(nullptr)},
          {"processes", t.look > 0 ? nlohmann::ordered_json(t.processes) : nlohmann::ordered_json(nullptr)}};
}

nlohmann::ordered_json look_json(const Look& l) {
  return {{"look", l.look},
          {"extra_repetitions", l.extra},
          {"cases", l.cases},
          {"repetitions", l.repetitions},
          {"confidence", json_number(l.confidence)},
          {"resamples", l.resamples},
          {"judged", l.judged},
          {"undecided", l.undecided},
          {"seconds", json_number(l.seconds)}};
}

/// Figure 5's line as description: slope, intercept, R^2, log-log exponent and the node range.
nlohmann::ordered_json fit_json(const StepFit& f) {
  const auto nodes = [&](bool last) {
    return f.points.empty() ? nlohmann::ordered_json(nullptr)
                            : json_number(last ? f.points.back().nodes : f.points.front().nodes);
  };
  return {{"method", f.method},
          {"points", f.points.size()},
          {"min_nodes", nodes(false)},
          {"max_nodes", nodes(true)},
          {"r2", json_number(f.r2)},
          {"slope_ms_per_node", json_number(f.slope_ms_per_node)},
          {"intercept_ms", json_number(f.intercept_ms)},
          {"loglog_exponent", json_number(f.loglog_exponent)}};
}

/// The fidelity row of TC-SB at a Table 2 row's target, when the run has a fidelity pass.
const FidelityRow* fidelity_row(const RunTables& tables, const Table2Row& row) {
  if (!tables.fidelity || row.method != "tcsb" || !row.compression) return nullptr;
  for (const FidelityRow& f : tables.fidelity->rows)
    if (f.method == "tcsb" && same_compression(f.compression, *row.compression) && f.nets > 0) return &f;
  return nullptr;
}

/// The looks taken, and what the verdicts rest on.
void print_looks(const Reproduction& reproduction, std::ostream& out) {
  TextTable t({{"look"},
               {"extra reps"},
               {"cases"},
               {"reps"},
               {"confidence"},
               {"resamples"},
               {"judged"},
               {"undecided"},
               {"seconds"}});
  for (const Look& l : reproduction.looks)
    t.add_row({std::to_string(l.look), std::to_string(l.extra), std::to_string(l.cases), std::to_string(l.repetitions),
               fixed(100.0 * l.confidence, 2) + "%", std::to_string(l.resamples), std::to_string(l.judged),
               std::to_string(l.undecided), fixed(l.seconds, 1)});
  out << "Looks (budget " << fixed(reproduction.budget_s, 0) << " s; ended: " << looks_ended_name(reproduction.ended)
      << "):\n";
  t.print(out);
  out << "A claim measured from repetitions passes when its whole interval satisfies it, fails when none of it does, "
         "and is undecided otherwise (percentile bootstrap of the repetitions, a net's cases drawn together so "
         "ratios stay paired, every net's when they took their turns together). Look k spends alpha/2^k of alpha = "
      << general(kSequentialAlpha, 2) << " (docs/methodology.md); a claim keeps the verdict of the look that "
      << "decided it. Counts and fidelity metrics are judged on their values.\n";
  const bool any_interval = std::any_of(reproduction.claims.begin(), reproduction.claims.end(),
                                        [](const TrackedClaim& c) { return c.claim.interval.has_value(); });
  if (!any_interval)
    out << "No intervals: they need at least " << kMinRepetitionsForIntervals << " repetitions per case.\n";
}

}  // namespace

nlohmann::ordered_json reproduction_json(const Reproduction& reproduction) {
  const ReproductionTables& tables = reproduction.tables;
  nlohmann::ordered_json t2 = nlohmann::ordered_json::array();
  for (const Table2Row& row : tables.run.whole.table2) {
    const PaperTable2Row* p = paper_row(reproduction.paper, row);
    nlohmann::ordered_json paper = nullptr;
    if (p)
      paper = {{"N", p->N},
               {"L", p->L},
               {"I", p->I},
               {"total_ms", p->total_ms},
               {"time_ratio_vs_plain", json_number(reproduction.paper.time_ratio(p->compression))}};
    if (p && p->method != "TC-SB") paper["time_ratio_vs_plain"] = 1.0;
    t2.push_back({{"method", row.method},
                  {"compression", row.compression_label},
                  {"paper", paper},
                  {"ours",
                   {{"N", json_number(row.N)},
                    {"L", json_number(row.L)},
                    {"I", json_number(row.I)},
                    {"total_ms", json_number(row.total_ms)},
                    {"time_ratio_vs_plain", json_number(row.time_ratio_vs_plain)},
                    {"node_ratio", json_number(row.node_ratio)}}}});
    if (row.time_ratio_vs_equal_plain)  // only in runs with plain_equal cases
      t2.back()["ours"]["time_ratio_vs_equal_plain"] = json_number(row.time_ratio_vs_equal_plain);
    // What the speed costs, from the fidelity pass (the `fidelity` section has every statistic).
    nlohmann::ordered_json error = nullptr;
    if (const FidelityRow* f = fidelity_row(tables.run, row))
      error = {{"rms_pct", json_number(f->rms_pct.mean)},
               {"max_pct", json_number(f->max_pct.max)},
               {"weighted_rms_pct", json_number(f->weighted_rms_pct.mean)},
               {"popping_pct", json_number(f->popping_pct.max)},
               {"energy_drift_pct", json_number(f->energy_drift_pct.mean)}};
    t2.back()["ours"]["fidelity"] = error;
  }
  nlohmann::ordered_json t1 = nlohmann::ordered_json::array();
  for (const Table1Row& row : tables.run.whole.table1) {
    const PaperTable1Row* p = paper_row(reproduction.paper, row.operation);
    nlohmann::ordered_json paper = nullptr;
    if (p)
      paper = {{"N", p->N},
               {"L", p->L},
               {"node_ops_ms", p->node_ops_ms},
               {"link_ops_ms", p->link_ops_ms},
               {"complete_ms", p->complete_ms}};
    const bool any = row.count > 0;
    const auto v = [&](double x) { return any ? json_number(x) : nlohmann::ordered_json(nullptr); };
    t1.push_back({{"operation", row.operation},
                  {"paper", paper},
                  {"ours",
                   {{"N", v(row.N)},
                    {"L", v(row.L)},
                    {"node_ops_ms", v(row.node_ops_ms)},
                    {"link_ops_ms", v(row.link_ops_ms)},
                    {"complete_ms", v(row.complete_ms)},
                    {"p50_us", v(row.p50_us)},
                    {"p99_us", v(row.p99_us)},
                    {"count", row.count}}}});
  }
  nlohmann::ordered_json claims = nlohmann::ordered_json::array(), targets = nlohmann::ordered_json::array(),
                         sanity = nlohmann::ordered_json::array(), looks = nlohmann::ordered_json::array();
  for (const TrackedClaim& c : reproduction.claims) claims.push_back(claim_json(c));
  for (const TrackedClaim& c : reproduction.targets) targets.push_back(claim_json(c));
  for (const TrackedClaim& c : reproduction.sanity) sanity.push_back(claim_json(c));
  for (const Look& l : reproduction.looks) looks.push_back(look_json(l));
  return {{"paper_source", reproduction.paper.source},
          {"paper_hardware", reproduction.paper.hardware},
          {"table1", t1},
          {"table2", t2},
          {"figure5",
           {{"description", "step time against simulated nodes, one least-squares line per method through "
                            "every usable case (TC-SB: all budgets); plain's is reported, not claimed"},
            {"plain", fit_json(tables.plain_fit)},
            {"tcsb", fit_json(tables.tcsb_fit)}}},
          {"claims", claims},
          {"targets", targets},
          {"sanity", sanity},
          {"verdict", verdict_name(reproduction.verdict())},
          {"sequential",
           {{"alpha", json_number(kSequentialAlpha)},
            {"correction", "look k spends alpha / 2^k: a central 1 - 2 alpha_k percentile bootstrap "
                           "interval, ceil(10 / alpha_k) resamples"},
            {"budget_s", json_number(reproduction.budget_s)},
            {"ended", looks_ended_name(reproduction.ended)},
            {"looks", looks}}},
          {"bootstrap_s", json_number(reproduction.bootstrap_s)},
          {"wall_s", json_number(reproduction.wall_s)}};
}

void print_reproduction(const Reproduction& reproduction, bool with_targets, std::ostream& out) {
  const ReproductionTables& tables = reproduction.tables;
  std::vector<TextTable::Column> columns{{"method", Align::kLeft},
                                         {"compression", Align::kLeft},
                                         {"paper N"},
                                         {"ours N"},
                                         {"paper L"},
                                         {"ours L"},
                                         {"paper I"},
                                         {"ours I"},
                                         {"paper ms"},
                                         {"ours ms"},
                                         {"paper ratio"},
                                         {"ours ratio"}};
  const std::vector<Table2Row>& rows = tables.run.whole.table2;
  const bool equal_plain =
      std::any_of(rows.begin(), rows.end(), [](const Table2Row& r) { return r.time_ratio_vs_equal_plain.has_value(); });
  // Beyond the paper: TC-SB against a static body of the nodes it simulates.
  if (equal_plain) columns.push_back({"ours/equal"});
  if (tables.run.fidelity) {  // the paper reports no error; ours, beside the speed it buys
    columns.push_back({"RMS %"});
    columns.push_back({"max %"});
    columns.push_back({"pop max %"});
  }
  TextTable t2(columns);
  for (const Table2Row& row : rows) {
    const PaperTable2Row* p = paper_row(reproduction.paper, row);
    const auto pv = [&](double x) { return p ? std::optional(x) : std::nullopt; };
    std::optional<double> paper_ratio;
    if (p) paper_ratio = p->method == "TC-SB" ? reproduction.paper.time_ratio(p->compression) : 1.0;
    std::vector<std::string> cells{row.method,
                                   row.compression_label,
                                   fixed(pv(p ? p->N : 0), 0),
                                   fixed(row.N, 0),
                                   fixed(pv(p ? p->L : 0), 0),
                                   fixed(row.L, 0),
                                   fixed(pv(p ? p->I : 0), 1),
                                   fixed(row.I, 1),
                                   fixed(pv(p ? p->total_ms : 0), 2),
                                   general(row.total_ms, 4),
                                   fixed(paper_ratio, 3),
                                   fixed(row.time_ratio_vs_plain, 3)};
    if (equal_plain) cells.push_back(fixed(row.time_ratio_vs_equal_plain, 3));
    if (const FidelityRow* f = fidelity_row(tables.run, row)) {
      cells.push_back(fixed(f->rms_pct.mean, 3));
      cells.push_back(fixed(f->max_pct.max, 3));
      cells.push_back(fixed(f->popping_pct.max, 3));
    }
    t2.add_row(std::move(cells));
  }
  out << "Table 2 beside the paper's (paper: " << reproduction.paper.hardware << "; ratios are to plain Bullet";
  if (equal_plain)
    out << "; ours/equal: TC-SB's time over plain_equal's, a static plain grid of the budget's node count, same run";
  if (tables.run.fidelity)
    out << "; RMS: error against full-resolution plain Bullet in % of the net's extent, mean over steps and nets; "
           "max and pop: max over steps and nets";
  out << "):\n";
  t2.print(out);

  TextTable t1({{"operation", Align::kLeft},
                {"paper N"},
                {"ours N"},
                {"paper us"},
                {"ours us"},
                {"ours p50 us"},
                {"ours p99 us"},
                {"paper node %"},
                {"ours node %"},
                {"count"}});
  for (const Table1Row& row : tables.run.whole.table1) {
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
  for (const Method method : {Method::kPlain, Method::kTcsb}) {
    const StepFit& f = method == Method::kPlain ? tables.plain_fit : tables.tcsb_fit;
    if (!f.valid) continue;
    out << "Figure 5, " << f.method << ": step ms = " << general(f.slope_ms_per_node.value_or(0) * 1000.0, 4)
        << " us x nodes + " << general(f.intercept_ms, 4) << " ms over " << f.points.size() << " cases ("
        << fixed(f.points.front().nodes, 0) << " to " << fixed(f.points.back().nodes, 0) << " nodes), R^2 "
        << general(f.r2, 4) << ", log-log exponent " << general(f.loglog_exponent, 3)
        << (method == Method::kPlain ? " (reported, not claimed)" : "") << "\n";
  }
  print_claims("Claims of the paper (any FAIL: exit 1; else any undecided: exit 4):", reproduction.claims, out);
  print_claims("Sanity of the measurement (reported, not gating; FAIL: a baseline to look at):", reproduction.sanity,
               out);
  if (with_targets)
    print_claims("Targets of this project (reported, not gating):", reproduction.targets, out);
  else  // they are not the paper's claims: in the JSON, and on the console when asked
    out << "Targets of this project (reported, not gating): " << reproduction.targets.size()
        << " in the JSON (reproduction.targets); --targets prints them\n";
  print_looks(reproduction, out);
  out << "Reproduction: " << verdict_text(reproduction.verdict()) << " (" << fixed(reproduction.wall_s, 1) << " s, "
      << reproduction.looks.size() << " look(s))\n";
}

}  // namespace tcsb
