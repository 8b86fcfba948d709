#include "suite/calibration_file.h"

#include <cmath>
#include <sstream>

#include "base/json_file.h"
#include "base/sha256.h"
#include "net/net_pins.h"
#include "suite/case_plan.h"
#include "suite/suite.h"
#include "suite/suite_fields.h"

namespace tcsb {

using namespace suite_fields;  // NOLINT: the suite's field vocabulary, for the same one-line errors

namespace {

constexpr int kCalibrationVersion = 1;
/// Bounds of a calibration file's input (it holds a few numbers).
constexpr std::size_t kMaxCalibrationBytes = 1 << 20;

const NumberRange kStiffness{0.0, true, 1.0, false};
const NumberRange kNonNegativeNumber{0.0, false};

nlohmann::ordered_json fit_json(const StiffnessFit& f, bool level) {
  nlohmann::ordered_json j;
  if (level)
    j["level"] = f.level;
  else
    j["compression"] = f.compression;
  j["linear_stiffness"] = f.linear_stiffness;
  j["rms_pct"] = f.rms_pct;
  j["uncalibrated_rms_pct"] = f.uncalibrated_rms_pct;
  j["evaluations"] = f.evaluations;
  return j;
}

StiffnessFit parse_fit(const Reader& r, const json& j, const std::string& path, bool level) {
  const Object o(r, j, path,
                 {level ? "level" : "compression", "linear_stiffness", "rms_pct", "uncalibrated_rms_pct",
                  "evaluations"});
  StiffnessFit f;
  if (level)
    o.read("level", f.level, 1, 64, true);
  else
    o.read("compression", f.compression, NumberRange{0.0, true, 1.0, true}, true);
  o.read("linear_stiffness", f.linear_stiffness, kStiffness, true);
  o.read("rms_pct", f.rms_pct, kNonNegativeNumber, true);
  o.read("uncalibrated_rms_pct", f.uncalibrated_rms_pct, kNonNegativeNumber, true);
  o.read("evaluations", f.evaluations, 0, 1000000, true);
  return f;
}

}  // namespace

std::vector<double> Calibration::level_stiffness() const {
  std::vector<double> out;
  for (const StiffnessFit& f : levels) out.push_back(f.linear_stiffness);
  return out;
}

std::optional<double> Calibration::uniform_stiffness(double compression) const {
  for (const StiffnessFit& f : uniform_grid)
    if (same_compression(f.compression, compression)) return f.linear_stiffness;
  return std::nullopt;
}

int calibrated_level_count(const std::vector<NetSpec>& nets, int max_levels) {
  int levels = max_levels;
  for (const NetSpec& n : nets) {
    int usable = 0;
    for (long long w = n.width, h = n.height; usable < levels;) {
      w = (w + 1) / 2;
      h = (h + 1) / 2;
      if (w < 5 || h < 5) break;
      ++usable;
    }
    levels = usable;
  }
  return levels;
}

int calibration_levels_needed(const Suite& suite) { return calibrated_level_count(suite.nets, kMaxCalibratedLevels); }

std::string calibration_key(const Suite& suite) {
  // Shortest round-trip text for every number, in a fixed order: equal settings give equal keys on every platform.
  std::ostringstream text;
  for (const NetSpec& n : suite.nets)
    text << "net " << n.width << ' ' << n.height << ' ' << fmt_number(n.size_x) << ' ' << fmt_number(n.size_z) << ' '
         << fmt_number(n.elevation) << ' ' << fmt_number(n.node_mass()) << ' ' << n.pinned_corners << ' '
         << n.shear_links << ' ' << n.bend_links << '\n';
  // Pins beyond the corners on lines of their own, only where a net has them: corner-only nets (every suite
  // written before edges and listed nodes) keep their keys, and their committed calibrations still match.
  for (std::size_t i = 0; i < suite.nets.size(); ++i) {
    const NetSpec& n = suite.nets[i];
    if (!pins_beyond_corners(n)) continue;
    text << "pins " << i << ' ' << n.pinned_edges;
    for (const GridNode& p : n.pinned_nodes) text << ' ' << p.x << ' ' << p.z;
    text << '\n';
  }
  text << "world " << fmt_number(suite.world.dt) << ' ' << fmt_number(suite.world.gravity) << '\n';
  text << "steps " << suite.steps << ' ' << suite.warmup_steps << '\n';
  text << "solver " << suite.solver.piterations << ' ' << suite.solver.viterations << ' ' << suite.solver.diterations
       << ' ' << fmt_number(suite.solver.damping) << ' ' << fmt_number(suite.solver.linear_stiffness) << '\n';
  text << "blend " << suite.tcsb.blend_steps << '\n';
  // The mass model changes every coarse level's cloth; only when not the paper's, so older keys stay as they were.
  if (suite.tcsb.masses == Masses::kCut) text << "masses cut\n";
  // So does the order Bullet solves the links in, where its solver does not converge (TcSettings::exact_order).
  if (suite.tcsb.exact_order) text << "order exact\n";
  // Whole-level cuts are reached by operations, in the scene: arrivals that collide later may settle elsewhere.
  if (!suite.tcsb.arrivals_collide) text << "arrivals at_end\n";
  // Not tcsb.interfaces: a calibration fits whole-level cuts, which have no boundary between levels.
  // A fit holds only in the scene it was made in. Only with colliders, so the keys of suites without a scene (and
  // the calibrations written for them) stay as they were.
  const SceneSettings& scene = suite.scene;
  const auto triple = [](const std::array<double, 3>& v) {
    return fmt_number(v[0]) + ' ' + fmt_number(v[1]) + ' ' + fmt_number(v[2]);
  };
  if (scene.has_colliders()) {
    text << "scene " << fmt_number(scene.margin) << ' ' << fmt_number(scene.friction) << ' '
         << fmt_number(scene.sdf_voxel) << '\n';
    // Without contact the cloth falls through the colliders: another regime. Only then, so the keys stay.
    if (!scene.rigid_contact) text << "collisions none\n";
    for (const Collider& c : scene.colliders) {
      text << "collider " << static_cast<int>(c.shape) << ' ' << static_cast<int>(c.motion) << ' ' << triple(c.position)
           << ' ' << fmt_number(c.radius) << ' ' << triple(c.half_extents) << ' ' << triple(c.normal) << ' '
           << triple(c.velocity) << ' ' << fmt_number(c.mass) << ' ' << fmt_number(c.friction);
      for (const VectorKey& k : c.path) text << " key " << fmt_number(k.time) << ' ' << triple(k.value);  // if any
      text << '\n';
    }
  }
  if (scene.pin_path.moves()) {  // likewise only with moving pins
    text << "pin_path " << triple(scene.pin_path.velocity);
    for (const VectorKey& k : scene.pin_path.keyframes) text << " key " << fmt_number(k.time) << ' ' << triple(k.value);
    text << '\n';
  }
  if (const std::optional<Wind>& w = scene.wind)  // likewise only with wind
    text << "wind " << aero_model_name(w->model) << ' ' << triple(w->velocity) << ' ' << fmt_number(w->lift) << ' '
         << fmt_number(w->drag) << ' ' << fmt_number(w->air_density) << '\n';
  return sha256_hex(text.str());
}

std::string calibration_json_text(const Calibration& c) {
  nlohmann::ordered_json doc;
  doc["tool"] = "tcsb";
  doc["calibration_version"] = kCalibrationVersion;
  doc["suite"] = c.suite;
  doc["key"] = c.key;
  doc["piterations"] = c.piterations;
  doc["linear_stiffness"] = c.linear_stiffness;
  doc["method"] =
      "per level: the link stiffness kLST of a TC-SB body whose whole cut is at that level (TC-SB's own masses and "
      "links), found by a one-dimensional search minimising the mean over the suite's nets of the mean-over-steps "
      "RMS distance from full-resolution plain Bullet (% of the net's extent); per budget: the same for the uniform "
      "grid of the budget's node count";
  nlohmann::ordered_json levels = nlohmann::ordered_json::array(), grids = nlohmann::ordered_json::array();
  for (const StiffnessFit& f : c.levels) levels.push_back(fit_json(f, true));
  for (const StiffnessFit& f : c.uniform_grid) grids.push_back(fit_json(f, false));
  doc["levels"] = std::move(levels);
  doc["uniform_grid"] = std::move(grids);
  return doc.dump(2) + "\n";
}

Calibration parse_calibration_file(const std::filesystem::path& path) {
  const std::string file = path.string();
  const Reader r(file);
  const std::string text = read_input_file(path, kMaxCalibrationBytes);  // InputError naming the file
  const json doc = parse_json_text<json>(text, file);
  if (!doc.is_object()) r.fail("", "a calibration must be a JSON object, got " + describe(doc));
  const Object root(r, doc, "",
                    {"tool", "calibration_version", "suite", "key", "piterations", "linear_stiffness", "method",
                     "levels", "uniform_grid"});
  if (r.string(root.need("tool"), "tool") != "tcsb") r.fail("tool", "must be \"tcsb\"");
  int version = 0;
  root.read("calibration_version", version, kCalibrationVersion, kCalibrationVersion, true);
  Calibration c;
  c.suite = r.string(root.need("suite"), "suite");
  c.key = r.string(root.need("key"), "key");
  root.read("piterations", c.piterations, 1, 100000, true);
  root.read("linear_stiffness", c.linear_stiffness, kStiffness, true);
  if (const json* m = root.find("method")) r.string(*m, "method");
  const json& levels = r.array(root.need("levels"), "levels", EmptyArray::kAllowed);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    c.levels.push_back(parse_fit(r, levels[i], index_path("levels", i), true));
    if (c.levels.back().level != static_cast<int>(i) + 1)
      r.fail(index_path("levels", i) + ".level", "must be " + std::to_string(i + 1) + " (levels in order from 1)");
  }
  const json& grids = r.array(root.need("uniform_grid"), "uniform_grid", EmptyArray::kAllowed);
  for (std::size_t i = 0; i < grids.size(); ++i)
    c.uniform_grid.push_back(parse_fit(r, grids[i], index_path("uniform_grid", i), false));
  return c;
}

std::string calibration_mismatch(const Calibration& c, const Suite& suite) {
  if (c.piterations != suite.solver.piterations)
    return "fitted at " + std::to_string(c.piterations) + " solver iterations, the suite runs " +
           std::to_string(suite.solver.piterations);
  if (c.linear_stiffness != suite.solver.linear_stiffness)
    return "fitted for material stiffness " + fmt_number(c.linear_stiffness) + ", the suite's is " +
           fmt_number(suite.solver.linear_stiffness);
  if (c.key != calibration_key(suite))
    return "fitted for other nets, dt, gravity, steps, solver settings or scene (key " + c.key.substr(0, 12) +
           "..., the suite's " + calibration_key(suite).substr(0, 12) + "...); run `tcsb calibrate` again";
  if (c.levels.empty()) return "it fits no LOD level (\"levels\": []): run `tcsb calibrate` again";
  if (const int needed = calibration_levels_needed(suite); static_cast<int>(c.levels.size()) < needed)
    return "it fits " + std::to_string(c.levels.size()) + " LOD level(s), the suite's nets need " +
           std::to_string(needed) + "; run `tcsb calibrate` again";
  for (const double t : suite.compression)
    if (t < 1.0 && !c.uniform_stiffness(t))
      return "it has no uniform-grid fit for the compression target " + fmt_number(t);
  return {};
}

}  // namespace tcsb
