#include "case/state_hash.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace tcsb {

namespace {
void mix(std::uint64_t& h, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h ^= bytes[i];
    h *= 1099511628211ULL;
  }
}
}  // namespace

std::string state_hash(const btSoftBody& body) {
  std::uint64_t h = 14695981039346656037ULL;
  const int nodes = body.m_nodes.size(), links = body.m_links.size();
  mix(h, &nodes, sizeof nodes);
  mix(h, &links, sizeof links);
  for (int i = 0; i < nodes; ++i) {
    const btScalar xyz[3] = {body.m_nodes[i].m_x.x(), body.m_nodes[i].m_x.y(), body.m_nodes[i].m_x.z()};
    mix(h, xyz, sizeof xyz);
  }
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

}  // namespace tcsb
