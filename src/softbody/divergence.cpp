#include "softbody/divergence.h"

#include <algorithm>
#include <cmath>

namespace tcsb {

namespace {
bool finite(const btVector3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }
}  // namespace

std::optional<std::string> quick_divergence_check(const btSoftBody& body, double max_extent) {
  const btVector3& lo = body.m_bounds[0];
  const btVector3& hi = body.m_bounds[1];
  if (!finite(lo) || !finite(hi)) return "non-finite body bounds (NaN or Inf position)";
  const btVector3 size = hi - lo;
  const double largest = std::max({size.x(), size.y(), size.z()});
  if (largest > max_extent)
    return "body extent " + std::to_string(largest) + " m exceeds the sane bound " + std::to_string(max_extent) + " m";
  return std::nullopt;
}

std::optional<std::string> full_divergence_check(const btSoftBody& body, double max_link_length) {
  for (int i = 0; i < body.m_nodes.size(); ++i)
    if (!finite(body.m_nodes[i].m_x) || !finite(body.m_nodes[i].m_v))
      return "non-finite position or velocity at node " + std::to_string(i);
  for (int i = 0; i < body.m_links.size(); ++i) {
    const btSoftBody::Link& l = body.m_links[i];
    const double length = (l.m_n[0]->m_x - l.m_n[1]->m_x).length();
    if (!(length <= max_link_length))
      return "link " + std::to_string(i) + " is " + std::to_string(length) + " m long (rest " + std::to_string(l.m_rl) +
             " m), beyond the sane bound " + std::to_string(max_link_length) + " m";
  }
  return std::nullopt;
}

std::optional<std::string> divergence_after_step(const btSoftBody& body, double net_extent, int step, int total) {
  std::optional<std::string> diverged = quick_divergence_check(body, kMaxExtentFactor * net_extent);
  if (!diverged && ((step + 1) % kFullCheckEvery == 0 || step + 1 == total))
    diverged = full_divergence_check(body, kMaxLinkLengthFactor * net_extent);
  return diverged;
}

std::optional<std::string> divergence_now(const btSoftBody& body, double net_extent) {
  std::optional<std::string> diverged = quick_divergence_check(body, kMaxExtentFactor * net_extent);
  if (!diverged) diverged = full_divergence_check(body, kMaxLinkLengthFactor * net_extent);
  return diverged;
}

}  // namespace tcsb
