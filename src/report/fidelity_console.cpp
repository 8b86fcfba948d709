#include "report/fidelity_console.h"

#include <ostream>

#include "fidelity/fidelity_result.h"
#include "paper/paper_tables.h"
#include "report/claims_console.h"
#include "report/text_table.h"

namespace tcsb {

namespace {

using Align = TextTable::Align;

std::optional<double> value(const MetricSummary& s, double v) { return s.count > 0 ? std::optional(v) : std::nullopt; }

void print_rows(const std::vector<FidelityRow>& rows, std::ostream& out) {
  TextTable t({{"method", Align::kLeft},
               {"compression", Align::kLeft},
               {"N"},
               {"RMS %"},
               {"RMS p95 %"},
               {"max %"},
               {"w-RMS %"},
               {"pop max %"},
               {"E drift %"},
               {"time/plain"},
               {"switch ms"},
               {"noise fl %"},
               {"interp fl %"},
               {"nets"},
               {"status", Align::kLeft}});
  for (const FidelityRow& r : rows) {
    t.add_row({r.method, compression_label(r.compression), fixed(r.N, 0), fixed(value(r.rms_pct, r.rms_pct.mean), 3),
               fixed(value(r.rms_pct, r.rms_pct.p95), 3), fixed(value(r.max_pct, r.max_pct.max), 3),
               fixed(value(r.weighted_rms_pct, r.weighted_rms_pct.mean), 3),
               fixed(value(r.popping_pct, r.popping_pct.max), 3),
               fixed(value(r.energy_drift_pct, r.energy_drift_pct.mean), 3), fixed(r.time_ratio_vs_plain, 3),
               fixed(r.switch_ms, 3), fixed(r.noise_floor_pct, 4), fixed(r.interpolation_floor_pct, 3),
               std::to_string(r.nets), r.status});
  }
  out << "Fidelity against full-resolution plain Bullet (% of net extent; RMS, w-RMS, E drift: mean over steps and "
         "nets; max and pop: max over steps and nets; time/plain: mean steps of this pass; noise fl, interp fl: "
         "the floors below):\n";
  t.print(out);
}

/// Per net: the noise floor and the interpolation floor at each of the suite's compression targets below 1.
void print_floors(const std::vector<FidelityFloors>& floors, const std::vector<double>& targets, std::ostream& out) {
  std::vector<TextTable::Column> columns{{"net", Align::kLeft}, {"noise floor %"}};
  std::vector<double> shown;
  for (const double t : targets)
    if (t < 1.0) {
      shown.push_back(t);
      columns.push_back({"interp floor " + compression_label(t) + " %"});
    }
  TextTable t(columns);
  for (const FidelityFloors& f : floors) {
    std::vector<std::string> cells{f.net_name, fixed(summary_mean(f.noise_rms_pct), 4)};
    for (const double target : shown) {
      std::optional<double> v;
      for (const InterpolationFloor& i : f.interpolation)
        if (same_compression(i.compression, target)) v = summary_mean(i.rms_pct);
      cells.push_back(fixed(v, 3));
    }
    t.add_row(cells);
  }
  out << "Floors (% of net extent, mean over steps): noise = the reference against itself with every initial "
         "position moved by 1e-6 of the extent; interp = the reference's surface through the budget's uniform rest "
         "grid, the error of a perfect body of that resolution:\n";
  t.print(out);
}

/// Per net and subject, the error as the spectator sees it, beside the net's noise floor in pixels (a scene with a
/// camera only).
void print_screen(const FidelityResult& fidelity, std::ostream& out) {
  TextTable t({{"net", Align::kLeft},
               {"method", Align::kLeft},
               {"compression", Align::kLeft},
               {"mean px"},
               {"p95 px"},
               {"max px"},
               {"steps p95>1px"},
               {"in view"},
               {"status", Align::kLeft}});
  const auto add = [&t](const std::string& net, const std::string& method, const std::string& compression,
                        const ScreenMetrics& s, const std::string& status) {
    t.add_row({net, method, compression, fixed(value(s.mean_px, s.mean_px.mean), 3),
               fixed(value(s.p95_px, s.p95_px.mean), 3), fixed(value(s.max_px, s.max_px.max), 2),
               fixed(100.0 * s.p95_over_1px_share, 1) + "%", fixed(s.points_in_view, 0), status});
  };
  for (const FidelityFloors& f : fidelity.floors)
    if (f.noise_screen) add(f.net_name, "noise floor", "", *f.noise_screen, "");
  for (const FidelityCase& c : fidelity.cases)
    if (c.screen) add(c.net_name, c.subject.method, compression_label(c.subject.body.compression), *c.screen, c.status);
  out << "Error in pixels as the camera sees it (per step over the grid points in view: mean, p95, max; then mean "
         "over steps, max for max; steps p95>1px: share of steps whose p95 exceeds one pixel; in view: grid points "
         "per step):\n";
  t.print(out);
}

void print_sweep(const char* title, const std::vector<ParetoPoint>& sweep, const MaxCompression& m, std::ostream& out) {
  TextTable t({{"compression", Align::kLeft},
               {"N"},
               {"time/plain"},
               {"RMS %"},
               {"worst net RMS %"},
               {"Pareto front", Align::kLeft}});
  for (const ParetoPoint& p : sweep)
    t.add_row({compression_label(p.compression), fixed(p.N, 0), fixed(p.time_ratio_vs_plain, 3), fixed(p.rms_pct, 3),
               fixed(p.worst_net_rms_pct, 3), p.on_front ? "yes" : ""});
  out << title << " time versus error (Pareto sweep):\n";
  t.print(out);
  // The budget, the error it keeps and the speed it buys, or that none qualifies.
  const auto answer = [&out](const std::optional<double>& compression, const char* error_name,
                             const std::optional<double>& rms, const std::optional<double>& ratio) {
    if (compression)
      out << compression_label(*compression) << " of the nodes (" << error_name << " " << fixed(rms, 3)
          << "%, time/plain " << fixed(ratio, 3) << ")\n";
    else
      out << "none of the targets qualifies\n";
  };
  out << "Maximal compression (it and every larger target keep the worst net's RMS <= " << fixed(m.threshold_pct, 2)
      << "% of the extent): ";
  answer(m.compression, "worst net RMS", m.rms_pct, m.time_ratio_vs_plain);
  out << "  on the mean over the nets instead: ";
  answer(m.mean_compression, "mean RMS", m.mean_rms_pct, m.mean_time_ratio_vs_plain);
}

}  // namespace

void print_fidelity_report(const RunResult& result, const RunTables& tables, std::ostream& out) {
  if (!result.fidelity || !tables.fidelity) return;
  const FidelityTables& computed = *tables.fidelity;
  print_rows(computed.rows, out);
  out << '\n';
  if (!result.fidelity->floors.empty()) {
    print_floors(result.fidelity->floors, result.suite.compression, out);
    out << '\n';
  }
  if (result.suite.scene.camera) {
    print_screen(*result.fidelity, out);
    out << '\n';
  }
  print_sweep("TC-SB", computed.sweep, computed.max_compression, out);
  out << '\n';
  if (!computed.calibrated_sweep.empty()) {
    print_sweep("Calibrated TC-SB", computed.calibrated_sweep, computed.calibrated_max_compression, out);
    out << '\n';
  }
  print_claims("Fidelity targets (reported, not gating):", computed.targets, out);
  out << "Fidelity pass: " << fixed(result.fidelity->wall_s, 1) << " s\n";
}

}  // namespace tcsb
