#include "fidelity/grid_state_transfer.h"

#include "fidelity/reconstruction.h"
#include "softbody/vector_conversion.h"

namespace tcsb {

void transfer_grid_state(const btSoftBody& from, GridSize from_grid, btSoftBody& to, const Net& to_net,
                         std::vector<Eigen::Vector3d>& x, std::vector<Eigen::Vector3d>& v,
                         std::vector<Eigen::Vector3d>& to_x, std::vector<Eigen::Vector3d>& to_v) {
  const GridSize to_grid{to_net.width(), to_net.height()};
  copy_positions(from, x);
  copy_velocities(from, v);
  to_x.resize(to_net.node_count());
  to_v.resize(to_net.node_count());
  resample_bilinear(from_grid, x, to_grid, to_x);
  resample_bilinear(from_grid, v, to_grid, to_v);
  for (int i = 0; i < to.m_nodes.size(); ++i) {
    btSoftBody::Node& n = to.m_nodes[i];
    if (to_net.pinned()[static_cast<std::size_t>(i)]) continue;  // at rest, where the old grid's pins are too
    n.m_x = n.m_q = to_bullet(to_x[static_cast<std::size_t>(i)]);
    n.m_v = to_bullet(to_v[static_cast<std::size_t>(i)]);
  }
  to.updateBounds();
}

}  // namespace tcsb
