#include "report/world_console.h"

#include <ostream>

#include "paper/world_equal_error.h"
#include "report/text_table.h"

namespace tcsb {

namespace {

/// The method as the tables name it: full resolution at fewer passes with its divisor.
std::string world_method_label(const WorldMethodResult& m) {
  return m.solver_divisor == 1 ? m.method : m.method + " /" + std::to_string(m.solver_divisor);
}

/// "2.31 [1.90, 2.60]", "<= 0.80 (at cheapest)", "not reached".
std::string world_speedup_cell(const EqualErrorRival& r) {
  if (r.status == EqualErrorStatus::kNotReached) return "not reached";
  if (r.status == EqualErrorStatus::kAtCheapest) return "<= " + fixed(r.speedup, 2) + " (at cheapest)";
  std::string cell = fixed(r.speedup, 2);
  if (r.interval) cell += " [" + fixed(r.interval->low, 2) + ", " + fixed(r.interval->high, 2) + "]";
  return cell;
}

void print_world_equal_error(const WorldEqualError& table, std::ostream& out) {
  using Align = TextTable::Align;
  const EqualErrorNet& scene = table.scene;
  out << "World pass, speed-up at equal error (tcsb_world's p95 px on each rival's curve of p95 px against step time, "
         "log-log, never extrapolated; noise floor "
      << fixed(scene.floor, 3) << " px; 95 % bootstrap over blocks)";
  if (!scene.missing.empty()) out << ": none, " << scene.missing;
  out << "\n";
  if (scene.missing.empty()) {
    TextTable t(
        {{"budget"}, {"N"}, {"ms"}, {"p95 px"}, {"vs discrete_lod", Align::kLeft}, {"vs full res", Align::kLeft}});
    for (const EqualErrorRow& r : scene.rows)
      t.add_row({fixed(r.compression, 2), fixed(r.nodes, 1), fixed(r.time_ms, 3), fixed(r.error, 2),
                 world_speedup_cell(r.grid), world_speedup_cell(r.full)});
    t.print(out);
  }
  out << "World budget against per-body budgets at the same total nodes (tcsb_body's p95 px at tcsb_world's N, "
         "log-log between its budgets; body/world above 1: the world budget errs less)\n";
  TextTable s({{"budget"}, {"N"}, {"world p95 px"}, {"body p95 px"}, {"body/world"}});
  for (const WorldSameNodesRow& r : table.same_nodes)
    s.add_row({fixed(r.budget, 2), fixed(r.nodes, 1), fixed(r.world_p95_px, 2),
               r.body_p95_px ? fixed(r.body_p95_px, 2) : std::string("outside"), fixed(r.ratio, 2)});
  s.print(out);
}

}  // namespace

void print_world_report(const RunResult& result, const RunTables& tables, std::ostream& out) {
  if (!result.world) return;
  const WorldResult& w = *result.world;
  using Align = TextTable::Align;
  TextTable t({{"method", Align::kLeft},
               {"budget"},
               {"status", Align::kLeft},
               {"mean nodes"},
               {"step ms"},
               {"boundary ms"},
               {"time/full"},
               {"p95 px"},
               {"pop max px"},
               {"changes"},
               {"ops"},
               {"undone"}});
  for (const WorldMethodResult& m : w.methods)
    t.add_row({world_method_label(m), fixed(m.budget, 2), m.status, fixed(m.mean_nodes, 1), fixed(m.step_ms, 3),
               fixed(m.boundary_ms, 3), fixed(m.step_ratio, 3), fixed(m.p95_px, 2), fixed(m.popping_px, 2),
               std::to_string(m.resolution_changes),
               m.churn ? std::to_string(m.churn->refines + m.churn->coarsens) : std::string(),
               m.churn ? std::to_string(m.churn->undone) : std::string()});
  out << "World pass: " << w.bodies << " bodies, " << w.scene_nodes
      << " nodes at full resolution; p95 px = the 95th percentile of the pixel error over every point of every body "
         "the camera sees, mean over steps; boundary ms = the part of the step before the world steps (TC-SB's "
         "blends, feedback and operations; discrete LOD's switches); time/full = median over blocks of the step's "
         "ratio to full resolution's; "
         "pop = the largest jump on the image where a body changed its resolution; ops = TC-SB's refines and coarsens "
         "begun, undone = those that undid one begun on the same block within two evaluations; full_resolution /d: "
         "the suite's passes a step divided by d\n";
  t.print(out);
  if (tables.world_equal_error) print_world_equal_error(*tables.world_equal_error, out);
}

}  // namespace tcsb
