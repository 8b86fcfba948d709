#include "softbody/solver_settings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tcsb {

namespace {

[[noreturn]] void refuse(const char* field, const std::string& need, double got) {
  std::ostringstream text;
  text << "SolverSettings: " << field << " must be " << need << ", got " << got;
  throw std::invalid_argument(text.str());
}

}  // namespace

void check_solver_settings(const SolverSettings& s) {
  // The suite reader's ranges (suite/suite_settings_table.cpp), for a library user who fills the struct in code: a kLST
  // of 0 divides every link constant by zero, a damping of 1 or more stops or reverses every node.
  if (s.piterations < 1 || s.piterations > 1000) refuse("piterations", "in [1, 1000]", s.piterations);
  if (s.viterations < 0 || s.viterations > 1000) refuse("viterations", "in [0, 1000]", s.viterations);
  if (s.diterations < 0 || s.diterations > 1000) refuse("diterations", "in [0, 1000]", s.diterations);
  if (!(s.damping >= 0 && s.damping < 1)) refuse("damping", "in [0, 1)", s.damping);
  if (!(s.linear_stiffness > 0 && s.linear_stiffness <= 1)) refuse("linear_stiffness", "in (0, 1]", s.linear_stiffness);
  if (!(std::isfinite(s.step_dt) && s.step_dt > 0)) refuse("step_dt", "a finite number > 0", s.step_dt);
  if (!s.compliant_model()) return;
  const CompliantMaterial& c = s.compliant;
  if (!(std::isfinite(c.stretch_stiffness) && c.stretch_stiffness > 0))
    refuse("compliant.stretch_stiffness", "a finite number > 0 (N/m)", c.stretch_stiffness);
  if (!(std::isfinite(c.density) && c.density > 0)) refuse("compliant.density", "a finite number > 0", c.density);
  if (!(std::isfinite(c.damping) && c.damping >= 0)) refuse("compliant.damping", "a finite number >= 0", c.damping);
  if (c.substeps < 1 || c.substeps > 4096) refuse("compliant.substeps", "in [1, 4096]", c.substeps);
  if (c.passes < 1 || c.passes > kMaxLinkPasses)
    refuse("compliant.passes", "in [1, " + std::to_string(kMaxLinkPasses) + "]", c.passes);
}

}  // namespace tcsb
