#include "report/fidelity_json.h"

#include "fidelity/fidelity_result.h"
#include "paper/fidelity_tables.h"
#include "report/equal_error_json.h"
#include "report/json_number.h"

namespace tcsb {

namespace {

using ojson = nlohmann::ordered_json;

ojson metric_json(const MetricSummary& s) {
  // Never measured (a diverged case, a row with no ok net): nulls, not misleading zeros.
  if (s.count == 0) return {{"mean", nullptr}, {"p95", nullptr}, {"max", nullptr}};
  return {{"mean", json_number(s.mean)}, {"p95", json_number(s.p95)}, {"max", json_number(s.max)}};
}

ojson screen_json(const ScreenMetrics& s) {
  return {{"mean_px", metric_json(s.mean_px)},
          {"p95_px", metric_json(s.p95_px)},
          {"max_px", metric_json(s.max_px)},
          {"p95_over_1px_share", json_number(s.p95_over_1px_share)},
          {"points_in_view", json_number(s.points_in_view)}};
}

ojson claim_json(const Claim& c) {
  return {{"id", c.id},
          {"description", c.description},
          {"comparison", comparison_name(c.comparison)},
          {"expected", json_number(c.expected)},
          {"measured", json_number(c.measured)},
          {"verdict", verdict_name(verdict(c))}};
}

ojson row_json(const FidelityRow& r) {
  ojson out = {{"method", r.method},
               {"compression", json_number(r.compression)},
               {"N", json_number(r.N)},
               {"rms_pct", metric_json(r.rms_pct)},
               {"max_pct", metric_json(r.max_pct)},
               {"weighted_rms_pct", metric_json(r.weighted_rms_pct)},
               {"popping_pct", metric_json(r.popping_pct)},
               {"energy_drift_pct", metric_json(r.energy_drift_pct)},
               {"time_ratio_vs_plain", json_number(r.time_ratio_vs_plain)},
               {"switch_ms", json_number(r.switch_ms)},
               {"worst_net_rms_pct", json_number(r.worst_net_rms_pct)},
               {"noise_floor_pct", json_number(r.noise_floor_pct)},
               {"interpolation_floor_pct", json_number(r.interpolation_floor_pct)},
               {"grid", r.grid.empty() ? ojson(nullptr) : ojson(r.grid)},
               {"nets", r.nets},
               {"status", r.status}};
  add_solver_divisor(r.method, r.solver_divisor, out);
  return out;
}

ojson numbers_json(const std::vector<double>& values) {
  ojson out = ojson::array();
  for (const double v : values) out.push_back(json_number(v));
  return out;
}

ojson case_json(const FidelityCase& c) {
  ojson out = {{"net", c.net_name},
               {"method", c.subject.method},
               {"compression", json_number(c.subject.body.compression)},
               {"target_nodes", c.target_nodes},
               {"N", json_number(c.mean_nodes)},
               {"grid", c.grid.empty() ? ojson(nullptr) : ojson(c.grid)},
               {"status", c.status},
               {"diverged_step", json_integer(c.diverged_step)},
               {"diverged_reason", c.diverged_reason},
               {"rms_pct", metric_json(c.rms_pct)},
               {"max_pct", metric_json(c.max_pct)},
               {"weighted_rms_pct", metric_json(c.weighted_rms_pct)},
               {"popping_pct", metric_json(c.popping_pct)},
               {"energy_drift_pct", metric_json(c.energy_drift_pct)},
               {"step_ms", json_number(c.step_ms)},
               {"reference_step_ms", json_number(c.reference_step_ms)},
               {"time_ratio_vs_plain",
                c.reference_step_ms > 0 ? json_number(c.step_ms / c.reference_step_ms) : ojson(nullptr)},
               {"switch_ms", json_number(c.switch_ms)},
               {"switch_step", json_integer(c.switch_step)},
               {"converged_step", json_integer(c.converged_step)},
               {"final_state_hash", c.final_state_hash}};
  add_solver_divisor(out["method"], c.subject.body.solver_divisor, out);
  out["block_step_ms"] = numbers_json(c.block_step_ms);
  // Only in a scene with a camera: every other result stays as it was.
  if (c.screen) out["screen"] = screen_json(*c.screen);
  return out;
}

ojson floors_json(const FidelityFloors& f) {
  ojson interpolation = ojson::array();
  for (const InterpolationFloor& i : f.interpolation)
    interpolation.push_back({{"compression", json_number(i.compression)},
                             {"grid", i.grid},
                             {"rms_pct", json_number(summary_mean(i.rms_pct))}});
  ojson out = {{"net", f.net_name},
               {"noise_floor_pct", json_number(summary_mean(f.noise_rms_pct))},
               {"interpolation_floor_pct", std::move(interpolation)}};
  if (f.noise_screen) out["noise_floor_screen"] = screen_json(*f.noise_screen);
  out["reference_block_step_ms"] = numbers_json(f.reference_block_step_ms);
  if (const std::optional<ReferenceSubsteps>& r = f.reference) {
    ojson doublings = ojson::array();
    for (const SubstepDoubling& d : r->doublings)
      doublings.push_back({{"substeps", d.substeps},
                           {"change_rms_pct", d.diverged ? ojson(nullptr) : json_number(d.change_rms_pct)},
                           {"noise_rms_pct", d.diverged ? ojson(nullptr) : json_number(d.noise_rms_pct)},
                           {"diverged", d.diverged}});
    out["reference"] = {{"substeps", r->substeps}, {"converged", r->converged}, {"doublings", std::move(doublings)}};
  }
  return out;
}

/// A method's time-versus-error sweep (`points`, from pareto_sweep) as JSON (`sweep`) and its maximal compression
/// (`best`); `label` names the method in the definition.
void add_sweep(const std::vector<ParetoPoint>& points, const MaxCompression& m, const std::string& label, ojson& sweep,
               ojson& best) {
  sweep = ojson::array();
  for (const ParetoPoint& p : points) {
    sweep.push_back({{"compression", json_number(p.compression)},
                     {"N", json_number(p.N)},
                     {"time_ratio_vs_plain", json_number(p.time_ratio_vs_plain)},
                     {"rms_pct", json_number(p.rms_pct)},
                     {"worst_net_rms_pct", json_number(p.worst_net_rms_pct)},
                     {"on_front", p.on_front}});
  }
  best = {{"threshold_pct", json_number(m.threshold_pct)},
          {"compression", json_number(m.compression)},
          {"worst_net_rms_pct", json_number(m.rms_pct)},
          {"time_ratio_vs_plain", json_number(m.time_ratio_vs_plain)},
          {"definition", "smallest " + label +
                             " budget (fraction of the net's nodes) at which it and every larger target keep the "
                             "worst net's mean-over-steps RMS error within threshold_pct of the net's extent"},
          // The same rule on the mean over the nets, the other fidelity targets' convention.
          {"mean_compression", json_number(m.mean_compression)},
          {"mean_rms_pct", json_number(m.mean_rms_pct)},
          {"mean_time_ratio_vs_plain", json_number(m.mean_time_ratio_vs_plain)}};
}

}  // namespace

void add_fidelity_json(const RunResult& result, const RunTables& tables, nlohmann::ordered_json& doc) {
  if (!result.fidelity || !tables.fidelity) return;
  const FidelityResult& f = *result.fidelity;
  const FidelitySettings& settings = result.suite.fidelity;
  const FidelityTables& computed = *tables.fidelity;
  const std::vector<FidelityRow>& rows = computed.rows;
  ojson row_list = ojson::array(), cases = ojson::array(), targets = ojson::array();
  for (const FidelityRow& r : rows) row_list.push_back(row_json(r));
  for (const FidelityCase& c : f.cases) cases.push_back(case_json(c));
  ojson floors = ojson::array();
  for (const FidelityFloors& n : f.floors) floors.push_back(floors_json(n));
  for (const Claim& c : computed.targets) targets.push_back(claim_json(c));
  ojson pareto_targets = ojson::array();
  for (const double t : settings.pareto_targets) pareto_targets.push_back(json_number(t));
  doc["fidelity"] = {
      {"reference", "plain Bullet at full resolution, same initial conditions, dt and steps, recorded once per net "
                    "after the timed repetitions (not part of any case's timing); each subject then runs alone and is "
                    "compared with the recorded frame of every measured step"},
      {"units", "distances in % of the net's extent, energy drift |E - E_ref| in % of the reference's initial energy "
                "M g h (y from 0), each per step and summarised as mean, p95 and max over the measured steps "
                "(popping: over every step, warm-up included); rows combine nets as mean of means "
                "and p95s, max of maxima; time_ratio_vs_plain = subject's mean step / reference's mean step, "
                "both timed in this pass; floors: mean over the measured steps of the RMS that no subject can be "
                "expected to beat, per net: noise_floor_pct (the reference against itself started with every initial "
                "position perturbed by 1e-6 of the extent) and interpolation_floor_pct per budget (the reference's "
                "surface sampled at the budget's uniform rest grid and interpolated back); rows: their mean over the "
                "row's nets"},
      {"rms_threshold_pct", json_number(settings.rms_threshold_pct)},
      {"ablations", settings.ablations},
      {"pareto_targets", std::move(pareto_targets)},
      {"rows", std::move(row_list)},
      {"cases", std::move(cases)},
      {"floors", std::move(floors)},
      {"targets", std::move(targets)},
      {"wall_s", json_number(f.wall_s)},
  };
  if (settings.geomorph_boundaries) doc["fidelity"]["geomorph_boundaries"] = *settings.geomorph_boundaries;
  if (settings.curves) {
    doc["fidelity"]["curves"] = {{"budgets", numbers_json(settings.curves->budgets)},
                                 {"solver_divisors", settings.curves->solver_divisors}};
    ojson equal_error = ojson::array();
    for (const EqualErrorNet& n : computed.equal_error) equal_error.push_back(equal_error_json(n, "uniform_grid"));
    doc["fidelity"]["equal_error"] = {
        {"definition",
         "per net, for the error TC-SB reaches at each budget (metric: p95_px with a camera, the mean over the "
         "measured "
         "steps of the per-step p95 pixel error; else rms_pct), the step time each rival's curve needs to reach it, "
         "interpolated in log-log between its two points around it and never extrapolated (not_reached: no point is "
         "that accurate; at_cheapest: its cheapest point already is, so time_ms and speedup are upper bounds); "
         "speedup = that time / TC-SB's; times are medians over the pass's interleaved blocks of 20 steps, the "
         "interval a 95 % percentile bootstrap over those blocks; errors below the noise floor count as the floor, "
         "which is also the reference's (full resolution at the suite's or the converged solver) point on both "
         "rival curves"},
        {"nets", std::move(equal_error)}};
  }
  // The sweep of TC-SB, and with a calibration that of calibrated TC-SB (written only then: older results lack it).
  add_sweep(computed.sweep, computed.max_compression, "TC-SB", doc["pareto"], doc["max_compression"]);
  if (!computed.calibrated_sweep.empty())
    add_sweep(computed.calibrated_sweep, computed.calibrated_max_compression, "calibrated TC-SB",
              doc["pareto_calibrated"], doc["max_compression_calibrated"]);
}

}  // namespace tcsb
