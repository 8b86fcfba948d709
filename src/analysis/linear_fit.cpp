#include "analysis/linear_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tcsb {

LinearFit fit_linear(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) throw std::invalid_argument("fit_linear: x and y differ in size");
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!std::all_of(x.begin(), x.end(), finite) || !std::all_of(y.begin(), y.end(), finite))
    throw std::invalid_argument("fit_linear: non-finite value (filter diverged data first)");

  LinearFit fit;
  fit.points = x.size();
  if (fit.points < 2) return fit;
  // Exact comparison on purpose: any spread in x, however small, defines a slope; a rank threshold would second-
  // guess the data.
  const auto [x_min, x_max] = std::minmax_element(x.begin(), x.end());
  if (*x_min == *x_max) return fit;

  const auto n = static_cast<Eigen::Index>(fit.points);
  const Eigen::Map<const Eigen::VectorXd> xs(x.data(), n);
  const Eigen::Map<const Eigen::VectorXd> ys(y.data(), n);

  // Centre x before solving: sizes such as node counts (1e3..1e6) would otherwise make the [1, x] columns badly
  // conditioned, and the intercept would absorb rounding error of order slope * x.
  const double x_mean = xs.mean();
  Eigen::MatrixXd design(n, 2);
  design.col(0).setOnes();
  design.col(1) = xs.array() - x_mean;
  const Eigen::Vector2d coef = design.colPivHouseholderQr().solve(ys);

  fit.slope = coef(1);
  fit.intercept = coef(0) - fit.slope * x_mean;
  const Eigen::VectorXd residuals = ys - design * coef;
  fit.residuals.assign(residuals.data(), residuals.data() + n);

  const double ss_res = residuals.squaredNorm();
  const double ss_tot = (ys.array() - ys.mean()).matrix().squaredNorm();
  // With an intercept, SS_res <= SS_tot, so constant y leaves only rounding in SS_res: the line fits exactly.
  fit.r2 = ss_tot > 0.0 ? std::clamp(1.0 - ss_res / ss_tot, 0.0, 1.0) : 1.0;
  fit.valid =
      std::isfinite(fit.slope) && std::isfinite(fit.intercept) && std::isfinite(ss_res) && std::isfinite(ss_tot);
  if (!fit.valid) {
    // Only reachable on overflow (values near the limits of double); never hand non-finite numbers out.
    fit = LinearFit{};
    fit.points = x.size();
  }
  return fit;
}

}  // namespace tcsb
