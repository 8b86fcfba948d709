#include "report/json_report.h"

#include <cmath>

#include "net/net_pins.h"
#include "paper/paper_tables.h"
#include "report/fidelity_json.h"
#include "report/op_work_json.h"
#include "report/world_json.h"
#include "suite/suite_axes.h"
#include "suite/suite_settings_table.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

/// A setting's value as a result records it: a number that is not finite as null, like every number of a result.
ojson result_value(const ojson& value) {
  if (value.is_number_float()) return json_number(value.get<double>());
  if (!value.is_array()) return value;
  ojson out = ojson::array();
  for (const ojson& v : value) out.push_back(result_value(v));
  return out;
}

/// The table's settings (suite/suite_settings_table.h) the suite block records for `s`, in table order, each under
/// its section: with `always`, those it always records, else those it records only when they matter (Written), so a
/// suite that does not use a setting writes the block it wrote before the setting existed and its results still
/// compare with older baselines.
void write_suite_settings(ojson& out, const Suite& s, bool always) {
  for (const SuiteSetting& row : suite_settings()) {
    if ((row.written == Written::kAlways) != always || !suite_setting_written(row, s)) continue;
    ojson& section = row.section().empty() ? out : out[std::string(row.section())];
    section[std::string(row.key())] = result_value(row.member.value(row, s));
  }
}

/// The nets as run: names and sizes, and pins only beyond the corners.
ojson nets_json(const std::vector<NetSpec>& net_specs) {
  ojson nets = ojson::array();
  for (const NetSpec& n : net_specs) {
    nets.push_back({{"name", n.name}, {"width", n.width}, {"height", n.height}, {"nodes", n.node_count()}});
    // Only pins beyond the corners (which the suite file, by its sha256, holds): a corner-pinned net writes what it
    // wrote before edges and listed nodes existed, so its results compare with older ones.
    if (pins_beyond_corners(n)) {
      ojson edges = ojson::array(), nodes = ojson::array();
      for (const PinnedEdge e : {kEdgeMinX, kEdgeMaxX, kEdgeMinZ, kEdgeMaxZ})
        if (n.pinned_edges & e) edges.push_back(pinned_edge_name(e));
      for (const GridNode& p : n.pinned_nodes) nodes.push_back({p.x, p.z});
      nets.back()["pinned"] = {{"corners", n.pinned_corners}, {"edges", std::move(edges)}, {"nodes", std::move(nodes)}};
    }
  }
  return nets;
}

/// The scene's block (only in a scene with colliders, a camera, wind or moving pins, like the penetrations of its
/// repetitions).
ojson scene_json(const SceneSettings& scene) {
  ojson colliders = ojson::array();
  for (const Collider& c : scene.colliders) colliders.push_back(collider_name(c));
  ojson out = {{"colliders", std::move(colliders)},
               {"margin", json_number(scene.margin)},
               {"friction", json_number(scene.friction)},
               {"sdf_voxel", json_number(scene.sdf_voxel)}};
  // Only when not Bullet's default, so results written before the setting read as before.
  if (!scene.rigid_contact) out["collisions"] = ojson::array();
  if (const std::optional<Camera>& c = scene.camera)
    out["camera"] = {
        {"fov_deg", json_number(c->fov_deg)}, {"image", {c->width_px, c->height_px}}, {"keyframes", c->path.size()}};
  // Only when on, so results written before the setting read as before.
  if (scene.camera && scene.camera->occlusion_cell_px > 0)
    out["camera"]["occlusion_cell_px"] = scene.camera->occlusion_cell_px;
  if (const std::optional<Wind>& w = scene.wind)
    out["wind"] = {{"model", aero_model_name(w->model)},
                   {"velocity",
                    {json_number(w->velocity[0]), json_number(w->velocity[1]), json_number(w->velocity[2])}},
                   {"lift", json_number(w->lift)},
                   {"drag", json_number(w->drag)},
                   {"air_density", json_number(w->air_density)}};
  // Only in a scene of many bodies, so results written before such scenes read as before.
  if (!scene.bodies.empty()) out["bodies"] = scene.bodies.size();
  if (const PinPath& p = scene.pin_path; p.moves()) {
    if (p.keyframes.empty())
      out["pin_path"] = {
          {"velocity", {json_number(p.velocity[0]), json_number(p.velocity[1]), json_number(p.velocity[2])}}};
    else
      out["pin_path"] = {{"keyframes", p.keyframes.size()}};
  }
  return out;
}

}  // namespace

ojson context_json(const Context& context, const Suite& suite) {
  // to_json(Context) sorts its keys; copying them in that order into an ordered object keeps the order stable.
  ojson out = ojson(to_json(context));
  out["suite_path"] = suite.path.string();
  out["suite_sha256"] = suite.sha256;
  out["seed"] = suite.seed;
  return out;
}

ojson suite_json(const Suite& s) {
  ojson methods = ojson::array();
  for (const Method m : s.methods) methods.push_back(method_name(m));
  ojson compression = ojson::array();
  for (const double c : s.compression) compression.push_back(json_number(c));
  ojson out = {{"name", s.name}, {"description", s.description}, {"path", s.path.string()}, {"sha256", s.sha256}};
  write_suite_settings(out, s, true);
  // What was actually run (a caller may have narrowed the file's methods, e.g. the default reproduction).
  out["nets"] = nets_json(s.nets);
  out["methods"] = std::move(methods);
  out["compression"] = std::move(compression);
  write_suite_settings(out, s, false);
  // Only under the compliant material, so a result of Bullet's model reads as it always did.
  if (s.solver.compliant_model()) {
    const CompliantMaterial& m = s.solver.compliant;
    out["material"] = {{"model", "compliant"},
                       {"stretch_stiffness", json_number(m.stretch_stiffness)},
                       {"density", json_number(m.density)},
                       {"damping", json_number(m.damping)},
                       {"substeps", m.substeps}};
    // Only when more than one, so a result of one pass a small step reads as it did before the field.
    if (m.passes != 1) out["material"]["passes"] = m.passes;
  }
  if (s.scene.has_colliders() || s.scene.camera || s.scene.wind || s.scene.pin_path.moves())
    out["scene"] = scene_json(s.scene);
  // Optional: only a suite with axes has it, so the block of a suite without stays as it always was.
  if (!s.axes.empty()) {
    ojson axes = ojson::object();
    for (const Axis& axis : s.axes) axes[axis.path] = ojson::parse(nlohmann::json(axis.values).dump());
    out["axes"] = std::move(axes);
  }
  return out;
}

namespace {

ojson summary_json(const Summary& s) {
  // An empty sample has no median: null, not a misleading 0 (the case's status says why).
  const auto value = [&](double v) { return s.count > 0 ? json_number(v) : ojson(nullptr); };
  return {{"count", s.count},    {"median", value(s.median)}, {"mean", value(s.mean)}, {"stddev", value(s.stddev)},
          {"cv", value(s.cv)},   {"p95", value(s.p95)},       {"p99", value(s.p99)},   {"min", value(s.min)},
          {"max", value(s.max)}, {"unstable", s.unstable}};
}

/// A repetition's step time: null when it diverged before timing a step (at step 0, say), as every reader expects
/// of a repetition without one; its status and diverged_step say why. A step takes time: 0 would read as a value.
ojson step_time_json(const RepetitionResult& r, double ms) {
  return r.status != "ok" && !(ms > 0) ? ojson(nullptr) : json_number(ms);
}

ojson instructions_json(const InstructionCount& count) {
  return {{"own", count.own}, {"bullet", count.bullet}, {"total", count.total()}};
}

ojson repetition_json(const RepetitionResult& r) {
  ojson j = {
      {"repetition", r.repetition},
      {"status", r.status},
      {"diverged_step", json_integer(r.diverged_step)},
      {"diverged_reason", r.diverged_reason},
      {"mean_step_ms", step_time_json(r, r.mean_step_ms)},
      {"median_step_ms", step_time_json(r, r.median_step_ms)},
      {"mean_nodes", json_number(r.mean_nodes)},
      {"mean_links", json_number(r.mean_links)},
      {"mean_interpolations", json_number(r.mean_interpolations)},
      {"mean_feedback_ms", json_number(r.mean_feedback_ms)},
      {"mean_feedback_total_ms", json_number(r.mean_feedback_total_ms)},
      {"operations", r.operations},
      {"final_state_hash", r.final_state_hash},
      {"build_ms", json_number(r.build_ms)},
  };
  // Merged results only: which shard (process) measured it. A run of one process writes what it always wrote.
  if (r.process > 0) j["process"] = r.process;
  if (r.instructions) j["instructions"] = instructions_json(*r.instructions);  // --measure instructions only
  if (r.penetrations)  // scenes with colliders only: results of the paper's scene keep their bytes
    j["penetrations"] = {{"node_steps", r.penetrations->node_steps},
                         {"deepest_pct", json_number(r.penetrations->deepest_pct)},
                         {"mean_contacts", json_number(r.penetrations->mean_contacts())}};
  return j;
}

/// A case's configuration: its label and axis values (only in runs of a suite with axes).
ojson configuration_json(const RunResult& result, const CaseResult& c) {
  return {{"label", result.suite.configurations[c.key.configuration].label},
          {"axes", configuration_values(result.suite, c.key.configuration)}};
}

ojson case_json(const RunResult& result, const CaseRatios& ratios, std::size_t index) {
  const CaseResult& c = result.cases[index];
  ojson reps = ojson::array();
  for (const RepetitionResult& r : c.repetitions) reps.push_back(repetition_json(r));
  ojson out = {
      {"label", c.label},
      {"net", c.net_name},
      {"method", method_name(c.key.method)},
      {"compression", json_number(c.key.compression)},
      {"target_nodes", c.target_nodes},
      {"net_nodes", c.net_nodes},
      {"net_links", c.net_links},
      {"status", c.status},
      {"mean_nodes", json_number(c.mean_nodes)},
      {"mean_links", json_number(c.mean_links)},
      {"mean_interpolations", json_number(c.mean_interpolations)},
      {"mean_feedback_ms", json_number(c.mean_feedback_ms)},
      {"mean_feedback_total_ms", json_number(c.mean_feedback_total_ms)},
      {"step_ms", summary_json(c.step_ms)},
      {"ratio_vs_plain", json_number(ratios.vs_plain)},
  };
  // TC-SB against the static plain grid of its budget, paired as ratio_vs_plain is: the per-net tax of adaptivity
  // (Table 2's time_ratio_vs_equal_plain averages the nets). Only where the run has that grid.
  if (ratios.has_equal_plain) out["ratio_vs_equal_plain"] = json_number(ratios.vs_equal_plain);
  out["step_breakdown_ms"] = {{"bullet", json_number(c.breakdown.bullet_ms)},
                              {"feedback", json_number(c.breakdown.feedback_ms)},
                              {"operations", json_number(c.breakdown.operations_ms)},
                              {"blending", json_number(c.breakdown.blending_ms)}};
  out["repetitions"] = std::move(reps);
  if (c.instructions) {  // --measure instructions only
    ojson functions = ojson::array();
    for (const FunctionCount& f : c.functions)
      functions.push_back({{"name", f.name}, {"instructions", f.instructions}});
    out["instructions"] = instructions_json(*c.instructions);
    out["instructions"]["functions"] = std::move(functions);
  }
  // Only TC-SB has TreeCut operations; the key stays absent elsewhere (and in results written before it existed).
  if (c.key.method == Method::kTcsb) out["op_work"] = op_work_json(c.ops.samples);
  if (c.key.configuration < result.suite.configurations.size()) out["configuration"] = configuration_json(result, c);
  return out;
}

ojson table1_json(const std::vector<Table1Row>& table) {
  ojson rows = ojson::array();
  for (const Table1Row& r : table) {
    rows.push_back({{"operation", r.operation},
                    {"N", json_number(r.N)},
                    {"L", json_number(r.L)},
                    {"node_ops_ms", json_number(r.node_ops_ms)},
                    {"link_ops_ms", json_number(r.link_ops_ms)},
                    {"complete_ms", json_number(r.complete_ms)},
                    {"node_ops_pct", json_number(r.node_ops_pct)},
                    {"link_ops_pct", json_number(r.link_ops_pct)},
                    {"count", r.count},
                    {"p50_us", json_number(r.p50_us)},
                    {"p99_us", json_number(r.p99_us)}});
  }
  return rows;
}

ojson table2_json(const std::vector<Table2Row>& table) {
  ojson rows = ojson::array();
  for (const Table2Row& r : table) {
    rows.push_back({{"method", r.method},
                    {"compression", json_number(r.compression)},
                    {"compression_label", r.compression_label},
                    {"N", json_number(r.N)},
                    {"L", json_number(r.L)},
                    {"I", json_number(r.I)},
                    {"total_ms", json_number(r.total_ms)},
                    {"time_ratio_vs_plain", json_number(r.time_ratio_vs_plain)},
                    {"node_ratio", json_number(r.node_ratio)},
                    {"nets", r.nets},
                    {"status", r.status}});
    // Optional: present only in runs with plain_equal cases (results written before it existed lack it).
    if (r.time_ratio_vs_equal_plain)
      rows.back()["time_ratio_vs_equal_plain"] = json_number(r.time_ratio_vs_equal_plain);
  }
  return rows;
}

ojson points_json(const std::vector<ScalingPoint>& points) {
  ojson out = ojson::array();
  for (const ScalingPoint& p : points) out.push_back({{"nodes", json_number(p.nodes)}, {"ms", json_number(p.ms)}});
  return out;
}

ojson scaling_json(const TableSet& set) {
  ojson steps = ojson::array();
  for (const StepFit& f : set.step_fits) {
    steps.push_back({{"method", f.method},
                     {"compression", json_number(f.compression)},
                     {"valid", f.valid},
                     {"slope_ms_per_node", json_number(f.slope_ms_per_node)},
                     {"intercept_ms", json_number(f.intercept_ms)},
                     {"r2", json_number(f.r2)},
                     {"points", points_json(f.points)}});
  }
  ojson ops = ojson::array();
  for (const OpFit& f : set.op_fits) {
    ops.push_back({{"operation", f.operation},
                   {"valid", f.valid},
                   {"slope_ms_per_node", json_number(f.slope_ms_per_node)},
                   {"intercept_ms", json_number(f.intercept_ms)},
                   {"r2", json_number(f.r2)},
                   {"flatness", json_number(f.flatness)},
                   {"points", points_json(f.points)}});
  }
  return {{"step_ms_vs_nodes", std::move(steps)}, {"op_ms_vs_nodes", std::move(ops)}};
}

/// One entry per configuration: its label, axis values, case count and its own Table 1, Table 2 and fits.
ojson configurations_json(const RunResult& result, const RunTables& tables) {
  ojson out = ojson::array();
  for (std::size_t c = 0; c < result.suite.configurations.size(); ++c) {
    const TableSet& set = tables.configurations[c];
    out.push_back({{"label", result.suite.configurations[c].label},
                   {"axes", configuration_values(result.suite, c)},
                   {"cases", set.cases.size()},
                   {"table1", table1_json(set.table1)},
                   {"table2", table2_json(set.table2)},
                   {"scaling", scaling_json(set)}});
  }
  return out;
}

}  // namespace

ojson native_json(const RunResult& result, const RunTables& tables) {
  ojson cases = ojson::array();
  bool diverged = false;
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    cases.push_back(case_json(result, tables.case_ratios[i], i));
    diverged = diverged || result.cases[i].status != "ok";
  }
  ojson doc;
  doc["schema_version"] = kNativeJsonSchemaVersion;
  doc["tool"] = "tcsb";
  doc["measure"] = measure_name(result.measure);
  doc["context"] = context_json(result.context, result.suite);
  doc["suite"] = suite_json(result.suite);
  doc["cases"] = std::move(cases);
  if (result.suite.configurations.empty()) {
    doc["table1"] = table1_json(tables.whole.table1);
    doc["table2"] = table2_json(tables.whole.table2);
    doc["scaling"] = scaling_json(tables.whole);
  } else {
    // With axes the tables and fits are per configuration (a mean over configurations would mix settings): they
    // are in `configurations`, and the run-wide ones stay empty rather than mislead.
    doc["table1"] = ojson::array();
    doc["table2"] = ojson::array();
    doc["scaling"] = {{"step_ms_vs_nodes", ojson::array()}, {"op_ms_vs_nodes", ojson::array()}};
    doc["configurations"] = configurations_json(result, tables);
  }
  add_fidelity_json(result, tables,
                    doc);  // fidelity, pareto, max_compression (and calibrated): only with a fidelity pass
  add_world_json(result, tables, doc);
  doc["status"] = diverged ? "diverged" : "ok";
  doc["wall_s"] = json_number(result.wall_s);
  return doc;
}

std::string json_text(const nlohmann::ordered_json& doc, int indent) {
  return doc.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace tcsb
