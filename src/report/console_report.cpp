#include "report/console_report.h"

#include <algorithm>
#include <ostream>

#include "base/terminal_text.h"
#include "paper/paper_tables.h"
#include "report/fidelity_console.h"
#include "report/text_table.h"
#include "report/world_console.h"

namespace tcsb {
namespace {

using Align = TextTable::Align;

std::optional<double> measured(const Summary& s, double v) {
  return s.count > 0 ? std::optional<double>(v) : std::nullopt;
}

/// A case's penetrations over its repetitions: the most node-steps any repetition had, the deepest node, and the
/// most contacts per step.
struct WorstContact {
  std::int64_t node_steps = 0;
  double deepest_pct = 0;
  double mean_contacts = 0;
};
WorstContact worst_penetrations(const CaseResult& c) {
  WorstContact worst;
  for (const RepetitionResult& rep : c.repetitions) {
    if (!rep.penetrations) continue;
    worst.node_steps = std::max(worst.node_steps, rep.penetrations->node_steps);
    worst.deepest_pct = std::max(worst.deepest_pct, rep.penetrations->deepest_pct);
    worst.mean_contacts = std::max(worst.mean_contacts, rep.penetrations->mean_contacts());
  }
  return worst;
}

void print_cases(const RunResult& r, const RunTables& tables, const std::vector<std::size_t>& cases,
                 std::ostream& out) {
  const bool any_equal = std::any_of(cases.begin(), cases.end(),
                                     [&tables](std::size_t i) { return tables.case_ratios[i].has_equal_plain; });
  const bool scene = r.suite.scene.has_colliders();
  std::vector<TextTable::Column> columns = {
      {"case", Align::kLeft}, {"status", Align::kLeft}, {"N"}, {"L"}, {"I"}, {"median ms"}, {"CV %"}, {"vs plain"}};
  if (any_equal) columns.push_back({"vs equal"});
  if (scene) {
    columns.push_back({"contacts"});
    columns.push_back({"inside"});
    columns.push_back({"deepest %"});
  }
  columns.push_back({"reps", Align::kRight});
  TextTable t(columns);
  for (const std::size_t i : cases) {
    const CaseResult& c = r.cases[i];
    const CaseRatios& ratios = tables.case_ratios[i];
    const bool ok = c.status == "ok";
    std::string status = c.status;
    if (c.step_ms.unstable) status += " (unstable)";
    std::vector<std::string> row = {c.label,
                                    status,
                                    fixed(ok ? std::optional(c.mean_nodes) : std::nullopt, 0),
                                    fixed(ok ? std::optional(c.mean_links) : std::nullopt, 0),
                                    fixed(ok ? std::optional(c.mean_interpolations) : std::nullopt, 1),
                                    general(measured(c.step_ms, c.step_ms.median), 4),
                                    fixed(measured(c.step_ms, 100.0 * c.step_ms.cv), 1),
                                    fixed(ratios.vs_plain, 3)};
    if (any_equal) row.push_back(fixed(ratios.vs_equal_plain, 3));
    if (scene) {
      const WorstContact worst = worst_penetrations(c);
      row.push_back(fixed(worst.mean_contacts, 0));
      row.push_back(std::to_string(worst.node_steps));
      row.push_back(fixed(worst.deepest_pct, 3));
    }
    row.push_back(std::to_string(c.step_ms.count) + "/" + std::to_string(c.repetitions.size()));
    t.add_row(row);
  }
  out << "Cases (median of per-repetition mean step times; 'vs plain' = median of paired same-run ratios";
  if (any_equal) out << "; 'vs equal' = the same against plain_equal, TC-SB's tax over a static grid of its budget";
  if (scene)
    out << "; 'contacts' = Bullet's rigid contacts per step (nodes within the margin of a collider), 'inside' = "
           "node-steps found inside a collider deeper than the contact margin, 'deepest %' = the deepest node in % of "
           "the net's extent, each the worst repetition's";
  out << "):\n";
  t.print(out);
}

void print_table1(const std::vector<Table1Row>& rows, std::ostream& out) {
  TextTable t({{"operation", Align::kLeft},
               {"N"},
               {"L"},
               {"node ms"},
               {"node %"},
               {"link ms"},
               {"link %"},
               {"complete ms"},
               {"p50 us"},
               {"p99 us"},
               {"count"}});
  const bool none = std::all_of(rows.begin(), rows.end(), [](const Table1Row& row) { return row.count == 0; });
  for (const Table1Row& row : none ? std::vector<Table1Row>{} : rows) {
    const bool any = row.count > 0;
    const auto v = [&](double x) { return any ? std::optional(x) : std::nullopt; };
    t.add_row({row.operation, fixed(v(row.N), 0), fixed(v(row.L), 0), fixed(v(row.node_ops_ms), 4),
               fixed(v(row.node_ops_pct), 2), fixed(v(row.link_ops_ms), 4), fixed(v(row.link_ops_pct), 2),
               fixed(v(row.complete_ms), 4), fixed(v(row.p50_us), 2), fixed(v(row.p99_us), 2),
               std::to_string(row.count)});
  }
  out << "Table 1: TreeCut operations (mean per operation over the TC-SB cases):\n";
  if (t.empty())
    out << "  (no TC-SB operations were recorded)\n";
  else
    t.print(out);
}

void print_table2(const std::vector<Table2Row>& rows, std::ostream& out) {
  const bool equal_plain = std::any_of(rows.begin(), rows.end(),
                                       [](const Table2Row& row) { return row.time_ratio_vs_equal_plain.has_value(); });
  std::vector<TextTable::Column> columns{{"method", Align::kLeft},
                                         {"compression", Align::kLeft},
                                         {"N"},
                                         {"L"},
                                         {"I"},
                                         {"total ms"},
                                         {"time/plain"},
                                         {"N/plain"},
                                         {"nets"},
                                         {"status", Align::kLeft}};
  if (equal_plain) columns.push_back({"time/equal"});
  TextTable t(columns);
  for (const Table2Row& row : rows) {
    std::vector<std::string> cells{row.method,
                                   row.compression_label,
                                   fixed(row.N, 0),
                                   fixed(row.L, 0),
                                   fixed(row.I, 1),
                                   general(row.total_ms, 4),
                                   fixed(row.time_ratio_vs_plain, 3),
                                   fixed(row.node_ratio, 3),
                                   std::to_string(row.nets),
                                   row.status};
    if (equal_plain) cells.push_back(fixed(row.time_ratio_vs_equal_plain, 3));
    t.add_row(std::move(cells));
  }
  out << "Table 2: per method and compression, averaged over the nets";
  if (equal_plain) out << " (time/equal: TC-SB over plain_equal, a static plain grid of the budget's node count)";
  out << ":\n";
  t.print(out);
}

void print_fits(const TableSet& set, std::ostream& out) {
  TextTable steps({{"method", Align::kLeft},
                   {"compression", Align::kLeft},
                   {"slope ms/node"},
                   {"intercept ms"},
                   {"R2"},
                   {"points"}});
  for (const StepFit& f : set.step_fits) {
    steps.add_row({f.method, compression_label(f.compression), general(f.slope_ms_per_node, 4),
                   fixed(f.intercept_ms, 4), fixed(f.r2, 4), std::to_string(f.points.size())});
  }
  out << "Step time vs nodes (linear fit, one point per net):\n";
  if (steps.empty())
    out << "  (no method has 2 or more ok nets)\n";
  else
    steps.print(out);

  TextTable ops({{"operation", Align::kLeft}, {"slope ms/node"}, {"intercept ms"}, {"R2"}, {"flatness"}, {"points"}});
  for (const OpFit& f : set.op_fits) {
    ops.add_row({f.operation, general(f.slope_ms_per_node, 4), general(f.intercept_ms, 4), fixed(f.r2, 4),
                 fixed(f.flatness, 3), std::to_string(f.points.size())});
  }
  out << "Operation time vs nodes (flat in N when flatness < " << fixed(kFlatnessTarget, 1) << "):\n";
  ops.print(out);
}

/// The cases, Table 1, Table 2 and the fits of one run (or one configuration's share of it).
void print_tables(const RunResult& r, const RunTables& tables, const TableSet& set, std::ostream& out) {
  print_cases(r, tables, set.cases, out);
  out << '\n';
  print_table1(set.table1, out);
  out << '\n';
  print_table2(set.table2, out);
  out << '\n';
  print_fits(set, out);
}

}  // namespace

void print_console_report(const RunResult& result, const RunTables& tables, std::ostream& out) {
  out << "Suite " << terminal_safe(result.suite.name) << " (" << terminal_safe(result.suite.path.string()) << "), "
      << result.cases.size() << " cases, ";
  if (!result.suite.configurations.empty()) out << result.suite.configurations.size() << " configurations, ";
  out << result.suite.repetitions << " repetitions x " << result.suite.steps << " steps, wall "
      << fixed(result.wall_s, 2) << " s\n\n";
  if (result.suite.configurations.empty()) {
    print_tables(result, tables, tables.whole, out);
  } else {
    // Grouped by configuration: each one's cases, tables and fits, as if it had run alone.
    const std::size_t count = result.suite.configurations.size();
    for (std::size_t c = 0; c < count; ++c) {
      out << (c == 0 ? "" : "\n") << "== Configuration " << c + 1 << " of " << count << ": "
          << terminal_safe(result.suite.configurations[c].label) << " ==\n\n";
      print_tables(result, tables, tables.configurations[c], out);
    }
  }
  if (result.fidelity) {
    out << '\n';
    print_fidelity_report(result, tables, out);
  }
  if (result.world) {
    out << '\n';
    print_world_report(result, tables, out);
  }
}

}  // namespace tcsb
