#include "suite/fidelity_block.h"

namespace tcsb {

using namespace suite_fields;

namespace {

/// The most a curve's divisor may divide the suite's passes: past 64 every suite here would be at one pass.
constexpr int kMaxSolverDivisor = 64;

/// The longest geomorph: a thousand boundaries, beyond any blend (tcsb.blend_steps' own bound).
constexpr int kMaxGeomorphBoundaries = 1000;

/// `values` ascending with no two equal, or a failure naming the first out of order.
template <class T>
void require_ascending(const Reader& r, const std::vector<T>& values, const std::string& path) {
  for (std::size_t i = 1; i < values.size(); ++i)
    if (!(values[i - 1] < values[i])) r.fail(index_path(path, i), "must be greater than the value before it");
}

FidelityCurves parse_curves(const Reader& r, const json& j, const std::string& path) {
  const Object c(r, j, path, {"budgets", "solver_divisors"});
  FidelityCurves curves;
  const json& budgets = r.array(c.need("budgets"), c.at("budgets"));
  for (std::size_t i = 0; i < budgets.size(); ++i) {
    const std::string at = index_path(c.at("budgets"), i);
    const double b = r.number(budgets[i], at, kFraction);
    if (b >= 1.0) r.fail(at, "must be below 1: full resolution is on every curve already");
    curves.budgets.push_back(b);
  }
  require_ascending(r, curves.budgets, c.at("budgets"));
  const json& divisors = r.array(c.need("solver_divisors"), c.at("solver_divisors"));
  for (std::size_t i = 0; i < divisors.size(); ++i)
    curves.solver_divisors.push_back(
        static_cast<int>(r.integer(divisors[i], index_path(c.at("solver_divisors"), i), 2, kMaxSolverDivisor)));
  require_ascending(r, curves.solver_divisors, c.at("solver_divisors"));
  return curves;
}

}  // namespace

void parse_fidelity(const Reader& r, const Object& root, Suite& s) {
  const json* j = root.find("fidelity");
  if (!j) return;
  const Object fi(r, *j, "fidelity",
                  {"enabled", "rms_threshold_pct", "pareto_targets", "ablations", "calibration", "curves",
                   "geomorph_boundaries"});
  fi.read("enabled", s.fidelity.enabled);
  fi.read("rms_threshold_pct", s.fidelity.rms_threshold_pct, kPositive);
  if (const json* targets = fi.find("pareto_targets")) {
    r.array(*targets, fi.at("pareto_targets"), EmptyArray::kAllowed);
    for (std::size_t i = 0; i < targets->size(); ++i)
      s.fidelity.pareto_targets.push_back(r.number((*targets)[i], index_path(fi.at("pareto_targets"), i), kFraction));
  }
  fi.read("ablations", s.fidelity.ablations);
  if (const json* c = fi.find("calibration")) {
    s.fidelity.calibration_path = r.string(*c, fi.at("calibration"));
    if (s.fidelity.calibration_path.empty()) r.fail(fi.at("calibration"), "must name a file");
  }
  if (const json* c = fi.find("curves")) s.fidelity.curves = parse_curves(r, *c, fi.at("curves"));
  if (const json* g = fi.find("geomorph_boundaries"))
    s.fidelity.geomorph_boundaries =
        static_cast<int>(r.integer(*g, fi.at("geomorph_boundaries"), 1, kMaxGeomorphBoundaries));
}

}  // namespace tcsb
