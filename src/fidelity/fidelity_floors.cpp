#include "fidelity/fidelity_floors.h"

namespace tcsb {

namespace {

/// splitmix64: a fixed, well-mixed sequence from a seed (std's distributions differ between library versions).
std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

/// Uniform in [-1, 1] from the top 53 bits.
double symmetric_unit(std::uint64_t& state) {
  return static_cast<double>(splitmix64(state) >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

}  // namespace

void perturb_positions(btSoftBody& body, double amplitude, std::uint64_t seed) {
  if (amplitude == 0) return;  // bit for bit: not even a + 0 rounding pass over the floats
  std::uint64_t state = seed;
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    btSoftBody::Node& n = body.m_nodes[i];
    btVector3 offset;
    for (int k = 0; k < 3; ++k) offset[k] = static_cast<btScalar>(amplitude * symmetric_unit(state));
    n.m_x += offset;
    n.m_q = n.m_x;  // at rest: the step's velocity comes from v, not from x - q
  }
  body.updateBounds();
}

void resample_through(GridSize fine, std::span<const Eigen::Vector3d> x, GridSize coarse,
                      std::vector<Eigen::Vector3d>& coarse_scratch, std::vector<Eigen::Vector3d>& out) {
  coarse_scratch.resize(coarse.count());
  out.resize(fine.count());
  resample_bilinear(fine, x, coarse, coarse_scratch);
  resample_bilinear(coarse, coarse_scratch, fine, out);
}

}  // namespace tcsb
