#include "softbody/pin_motion.h"

namespace tcsb {

StockPins::StockPins(const btSoftBody& body) {
  for (int i = 0; i < body.m_nodes.size(); ++i)
    if (body.m_nodes[i].m_im == 0) pins_.push_back({i, body.m_nodes[i].m_x});
}

void StockPins::move(btSoftBody& body, const btVector3& offset, btScalar dt) const {
  for (const Pin& p : pins_) {
    btSoftBody::Node& n = body.m_nodes[p.node];
    n.m_v = pin_velocity(p.rest, offset, n.m_x, dt);
  }
}

}  // namespace tcsb
