#include "report/fidelity_console.h"

#include <ostream>

#include "paper/fidelity_tables.h"
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
               {"nets"},
               {"status", Align::kLeft}});
  for (const FidelityRow& r : rows) {
    t.add_row({r.method, compression_label(r.compression), fixed(r.N, 0), fixed(value(r.rms_pct, r.rms_pct.mean), 3),
               fixed(value(r.rms_pct, r.rms_pct.p95), 3), fixed(value(r.max_pct, r.max_pct.max), 3),
               fixed(value(r.weighted_rms_pct, r.weighted_rms_pct.mean), 3),
               fixed(value(r.popping_pct, r.popping_pct.max), 3),
               fixed(value(r.energy_drift_pct, r.energy_drift_pct.mean), 3), fixed(r.time_ratio_vs_plain, 3),
               fixed(r.switch_ms, 3), std::to_string(r.nets), r.status});
  }
  out << "Fidelity against full-resolution plain Bullet (% of net extent; RMS, w-RMS, E drift: mean over steps and "
         "nets; max and pop: max over steps and nets; time/plain: mean steps of this pass):\n";
  t.print(out);
}

void print_sweep(const std::vector<ParetoPoint>& sweep, const MaxCompression& m, std::ostream& out) {
  TextTable t({{"compression", Align::kLeft},
               {"N"},
               {"time/plain"},
               {"RMS %"},
               {"worst net RMS %"},
               {"Pareto front", Align::kLeft}});
  for (const ParetoPoint& p : sweep)
    t.add_row({compression_label(p.compression), fixed(p.N, 0), fixed(p.time_ratio_vs_plain, 3), fixed(p.rms_pct, 3),
               fixed(p.worst_net_rms_pct, 3), p.on_front ? "yes" : ""});
  out << "TC-SB time versus error (Pareto sweep):\n";
  t.print(out);
  out << "Maximal compression (it and every larger target keep the worst net's RMS <= " << fixed(m.threshold_pct, 2)
      << "% of the extent): ";
  if (m.compression)
    out << compression_label(*m.compression) << " of the nodes (worst net RMS " << fixed(m.rms_pct, 3)
        << "%, time/plain " << fixed(m.time_ratio_vs_plain, 3) << ")\n";
  else
    out << "none of the targets qualifies\n";
}

}  // namespace

void print_fidelity_report(const RunResult& result, std::ostream& out) {
  if (!result.fidelity) return;
  const std::vector<FidelityRow> rows = fidelity_rows(*result.fidelity);
  print_rows(rows, out);
  out << '\n';
  const std::vector<ParetoPoint> sweep = pareto_sweep(rows);
  print_sweep(sweep, max_compression(sweep, result.fidelity->rms_threshold_pct), out);
  out << '\n';
  print_claims("Fidelity targets (reported, not gating):", fidelity_targets(rows), out);
  out << "Fidelity pass: " << fixed(result.fidelity->wall_s, 1) << " s\n";
}

}  // namespace tcsb
