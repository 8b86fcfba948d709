// Moving pins (kinematic attachments): pinned nodes carried along a scripted offset from their rest positions, as
// if a rod held the cloth and someone moved it. A pinned node has zero inverse mass, so nothing in Bullet's step
// changes its velocity (gravity, forces, links, contacts and aerodynamics all scale by m_im), yet predictMotion
// moves every node by it (x += v dt, btSoftBody.cpp@3.24 line 2146). Setting a pinned node's velocity before a step
// therefore puts it exactly where the path says after it. The velocity is aimed at the target from where the node
// is, not derived from the offset's change, so float rounding never accumulates over a long path.
//
// One rule for every body: TcSoftBody::move_pins uses pin_velocity() on its pinned nodes, and StockPins on a stock
// body's (the plain baseline, CreatePatch's, the uniform grid), so on the finest cut both move bit for bit alike.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <vector>

namespace tcsb {

/// The velocity that carries a pinned node from `x` to `rest` + `offset` in one predictMotion of `dt`.
inline btVector3 pin_velocity(const btVector3& rest, const btVector3& offset, const btVector3& x, btScalar dt) {
  return (rest + offset - x) / dt;
}

/// The pinned nodes of a stock btSoftBody (zero inverse mass) and their rest positions, taken when it is built: its
/// node array never changes, so indices stay valid. For a TcSoftBody use its move_pins().
class StockPins {
 public:
  StockPins() = default;
  /// Takes every node of zero inverse mass, at its position now, as a pin at rest. O(N) once.
  explicit StockPins(const btSoftBody& body);
  /// Over the next step, moves every pin to its rest position + `offset` (sets its velocity). Call right before the
  /// step. O(pins).
  void move(btSoftBody& body, const btVector3& offset, btScalar dt) const;
  std::size_t size() const { return pins_.size(); }

 private:
  struct Pin {
    int node;
    btVector3 rest;
  };
  std::vector<Pin> pins_;
};

}  // namespace tcsb
