#include "analysis/sequential_looks.h"

#include <cmath>
#include <stdexcept>

namespace tcsb {

double look_alpha(double alpha, int look) {
  if (look < 1 || !(alpha > 0.0 && alpha < 1.0))
    throw std::invalid_argument("look_alpha: look must be >= 1 and alpha in (0, 1)");
  return std::ldexp(alpha, -look);
}

double look_confidence(double alpha, int look) { return 1.0 - 2.0 * look_alpha(alpha, look); }

int look_resamples(double alpha, int look) {
  // The small epsilon keeps 10 / 0.025 = 400 at 400 despite binary noise.
  return static_cast<int>(std::ceil(kReplicatesPerTail / look_alpha(alpha, look) - 1e-9));
}

}  // namespace tcsb
