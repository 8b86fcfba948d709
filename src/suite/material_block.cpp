#include "suite/material_block.h"

#include <algorithm>

namespace tcsb {

using namespace suite_fields;

/// The most small steps a step may take: past it a float's step h^2 g is below an ulp of any coordinate the nets
/// can have (docs/design.md, "Precision"), and the step's cost grows with each.
constexpr int kMaxSubsteps = 4096;

const char* material_model_name(MaterialModel model) {
  return model == MaterialModel::kCompliant ? "compliant" : "bullet";
}

void parse_material(const Reader& r, const Object& root, const nlohmann::json& nets, Suite& s) {
  const json* j = root.find("material");
  if (!j) return;
  const Object m(r, *j, "material", {"model", "stretch_stiffness", "density", "damping", "substeps", "passes"});
  SolverSettings& solver = s.solver;
  solver.model = r.choice<MaterialModel>(
      m.need("model"), m.at("model"), {{"bullet", MaterialModel::kBullet}, {"compliant", MaterialModel::kCompliant}});
  if (solver.model == MaterialModel::kBullet) {
    for (const char* key : {"stretch_stiffness", "density", "damping", "substeps", "passes"})
      if (m.find(key))
        r.fail(m.at(key), "is a setting of the compliant model; the bullet model takes its stiffness from solver");
    return;
  }
  CompliantMaterial& c = solver.compliant;
  m.read("stretch_stiffness", c.stretch_stiffness, kSceneQuantity, true);  // (bounded as what Bullet can carry)
  m.read("density", c.density, kSceneQuantity, true);
  m.read("damping", c.damping, kSceneNonNegative);
  m.read("substeps", c.substeps, 1, kMaxSubsteps, true);
  m.read("passes", c.passes, 1, kMaxLinkPasses);  // (optional: one pass, as before the field)
  // One material for every body: the nets' masses are its density's, lumped by area.
  for (std::size_t i = 0; i < s.nets.size(); ++i) {
    if (nets[i].contains("mass"))
      r.fail(index_path("nets", i) + ".mass",
             "the compliant material's masses come from material.density (kg/m^2), not from a net's mass");
    s.nets[i].mass_mode = MassMode::kDensity;
    s.nets[i].mass = c.density;
  }
}

void check_material(const Reader& r, const Suite& s) {
  const auto runs = [&](Method m) { return std::find(s.methods.begin(), s.methods.end(), m) != s.methods.end(); };
  if (!s.solver.compliant_model()) {
    if (runs(Method::kStock)) {
      const auto at = std::find(s.methods.begin(), s.methods.end(), Method::kStock) - s.methods.begin();
      r.fail(index_path("methods", static_cast<std::size_t>(at)),
             "\"stock\" is stock Bullet beside a compliant suite's bodies (material.model \"compliant\"); under the "
             "bullet model \"plain\" is that body");
    }
    return;
  }
  // The compliant model's stiffness is the material's: a per-level kLST would be a second material.
  if (!s.fidelity.calibration_path.empty())
    r.fail("fidelity.calibration",
           "the compliant material takes no calibration: its stiffness is material.stretch_stiffness at every level");
  // Bullet's kLST makes only the stock baseline; without it, it would be read and ignored.
  if (s.solver.linear_stiffness != 1.0 && !runs(Method::kStock))
    r.fail("solver.stiffness",
           "is Bullet's kLST, which under material.model \"compliant\" sets only the stock Bullet baseline (method "
           "\"stock\"), and this suite does not run it");
  // The cells the compliance is computed from are those of masses that follow the cut.
  if (runs(Method::kTcsb) && s.tcsb.masses != Masses::kCut)
    r.fail("tcsb.masses", "must be \"cut\" under the compliant material (its links' compliance and masses come from "
                          "the cut's cells)");
  for (const Axis& a : s.axes)
    if (a.path == "solver.stiffness" && !runs(Method::kStock))
      r.fail("axes", "solver.stiffness is Bullet's kLST, which the compliant material does not use");
}

}  // namespace tcsb
