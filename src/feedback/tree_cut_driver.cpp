#include "feedback/tree_cut_driver.h"

#include <algorithm>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace tcsb {

namespace {

/// The worlds with a driver, and their drivers: how the callback finds its driver (not through the world's user
/// info, which the application may set again with a post-tick callback of its own), and how a second driver on one
/// world is refused.
struct Registry {
  std::mutex mutex;
  std::vector<std::pair<const btDynamicsWorld*, TreeCutDriver*>> drivers;
};
Registry& registry() {
  static Registry r;
  return r;
}

/// The world's pre-tick callback, which btDynamicsWorld keeps protected and has no getter for: read through a
/// pointer to the member, taken in a class derived from it (never instantiated), as C++ allows.
struct PreTickPeek : btDynamicsWorld {
  static btInternalTickCallback of(const btDynamicsWorld& world) {
    return world.*(&PreTickPeek::m_internalPreTickCallback);
  }
};

std::string describe(const btSoftBody& body) {
  std::ostringstream s;
  s << (dynamic_cast<const TcSoftBody*>(&body) != nullptr ? "TcSoftBody" : "soft body") << " at "
    << static_cast<const void*>(&body);
  return s.str();
}

}  // namespace

TreeCutDriver::TreeCutDriver(btSoftRigidDynamicsWorld& world, Install install) : world_(world), install_(install) {
  {
    std::lock_guard<std::mutex> lock(registry().mutex);
    for (const auto& [w, d] : registry().drivers)
      if (w == &world)
        throw std::logic_error(
            "TreeCutDriver: this world already has a TreeCutDriver; one driver drives every TC-SB body of its world "
            "(hand the body to it with drive())");
    if (install == Install::kCallback && PreTickPeek::of(world) != nullptr)
      throw std::logic_error(
          "TreeCutDriver: the world already has a pre-tick callback; build the driver with Install::kManual and call "
          "pre_tick() first from that callback");
    registry().drivers.emplace_back(&world, this);
  }
  if (install == Install::kCallback) world.setInternalTickCallback(&TreeCutDriver::callback, this, true);
}

TreeCutDriver::~TreeCutDriver() {
  if (install_ == Install::kCallback && PreTickPeek::of(world_) == &TreeCutDriver::callback)
    world_.setInternalTickCallback(nullptr, nullptr, true);
  for (const auto& e : entries_) e->body->set_lifetime_listener(nullptr);
  std::lock_guard<std::mutex> lock(registry().mutex);
  auto& drivers = registry().drivers;
  drivers.erase(std::remove_if(drivers.begin(), drivers.end(), [this](const auto& p) { return p.second == this; }),
                drivers.end());
}

void TreeCutDriver::check_world_info(const btSoftBody& body, bool from_tick) const {
  if (body.m_worldInfo == &world_.getWorldInfo()) return;
  const std::string what =
      describe(body) +
      " was built with a btSoftBodyWorldInfo that is not this world's getWorldInfo() (its broadphase, dispatcher and "
      "sparse SDF): build it with world.getWorldInfo()";
  if (from_tick)
    throw std::logic_error("TreeCutDriver: " + what + "; the world's step would crash in btSoftBody::updateBounds");
  throw std::invalid_argument("TreeCutDriver::drive: " + what);
}

TreeCutDriver::Entry* TreeCutDriver::find(const TcSoftBody& body) {
  for (const auto& e : entries_)
    if (e->body == &body) return e.get();
  return nullptr;
}

const TreeCutDriver::Entry* TreeCutDriver::find(const TcSoftBody& body) const {
  for (const auto& e : entries_)
    if (e->body == &body) return e.get();
  return nullptr;
}

TreeCutDriver::Entry& TreeCutDriver::adopt(TcSoftBody& body) {
  if (Entry* e = find(body)) return *e;
  if (body.lifetime_listener() != nullptr && body.lifetime_listener() != this)
    throw std::invalid_argument("TreeCutDriver: " + describe(body) +
                                " is driven by another TreeCutDriver (of another world)");
  entries_.push_back(std::make_unique<Entry>());
  entries_.back()->body = &body;
  body.set_lifetime_listener(this);
  return *entries_.back();
}

void TreeCutDriver::quiesce(Entry& e) {
  // A parallel controller's worker may be reading the body's cut since the last step: joined (after_step sees the
  // step the body took) and put to sleep, so that whatever happens to the body next, nothing reads it.
  if (e.controller != nullptr && e.stepped) {
    e.controller->after_step(*e.body);
    e.controller->pause();
  }
  e.stepped = false;
}

void TreeCutDriver::drive(TcSoftBody& body, Controller* controller) {
  check_world_info(body, false);
  Entry& e = adopt(body);
  quiesce(e);  // the controller it had, if any, lets go of it
  e.controller = controller;
  e.owned.reset();
}

void TreeCutDriver::drive(TcSoftBody& body, std::unique_ptr<Controller> controller) {
  check_world_info(body, false);
  Entry& e = adopt(body);
  quiesce(e);
  e.controller = controller.get();
  e.owned = std::move(controller);
}

void TreeCutDriver::release(TcSoftBody& body) {
  const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e->body == &body; });
  if (it == entries_.end()) return;
  quiesce(**it);
  body.set_lifetime_listener(nullptr);
  entries_.erase(it);
}

Controller* TreeCutDriver::controller(const TcSoftBody& body) const {
  const Entry* e = find(body);
  return e != nullptr ? e->controller : nullptr;
}

namespace {
Controller& controller_of(const TreeCutDriver& driver, const TcSoftBody& body) {
  Controller* c = driver.controller(body);
  if (c == nullptr)
    throw std::invalid_argument("TreeCutDriver: no controller drives this body (drive(body, controller))");
  return *c;
}
}  // namespace

void TreeCutDriver::set_budget(const TcSoftBody& body, int nodes) { controller_of(*this, body).set_budget(nodes); }

void TreeCutDriver::set_spectator(const TcSoftBody& body, const Spectator& spectator) {
  controller_of(*this, body).set_spectator(spectator);
}

long long TreeCutDriver::ticks(const TcSoftBody& body) const {
  const Entry* e = find(body);
  return e != nullptr ? e->ticks : 0;
}

void TreeCutDriver::body_destroyed(TcSoftBody& body) {
  // Out of the world first: Bullet's world keeps the body's address and would step it at the next stepSimulation.
  btSoftBodyArray& bodies = world_.getSoftBodyArray();
  if (bodies.findLinearSearch(&body) < bodies.size()) world_.removeSoftBody(&body);
  const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e->body == &body; });
  if (it == entries_.end()) return;
  quiesce(**it);  // while the body is still whole
  entries_.erase(it);
}

void TreeCutDriver::set_world_budget(std::optional<int> nodes, double hysteresis) {
  if (nodes && *nodes < 1) throw std::invalid_argument("TreeCutDriver::set_world_budget: the budget must be >= 1");
  world_budget_ = nodes;
  world_hysteresis_ = hysteresis;
}

void TreeCutDriver::pre_tick() {
  for (const auto& e : entries_) e->seen = false;
  btSoftBodyArray& bodies = world_.getSoftBodyArray();
  // Every soft body first: one built with another world info crashes in Bullet's step, so none is operated on.
  for (int i = 0; i < bodies.size(); ++i) check_world_info(*bodies[i], true);
  // First every body's controller sees the last step, so a world budget weighs all of their rankings; then each
  // body's blends move on and its operations begin. (The bodies' cuts do not touch each other: the order between
  // bodies changes nothing else.)
  ticking_.clear();
  for (int i = 0; i < bodies.size(); ++i) {
    auto* body = dynamic_cast<TcSoftBody*>(bodies[i]);
    if (body == nullptr) continue;
    Entry& e = adopt(*body);
    e.seen = true;
    if (e.controller != nullptr) {
      if (e.stepped)
        e.controller->after_step(*body);
      else if (e.ticks > 0)
        e.controller->resume();  // back after a while out of the world (or with a new controller: a no-op)
    }
    ticking_.push_back(&e);
  }
  if (world_budget_) {
    members_.clear();
    for (Entry* e : ticking_)
      if (e->controller != nullptr) members_.push_back({e->body, e->controller});
    share_world_budget(members_, *world_budget_, world_hysteresis_);
  }
  for (Entry* e : ticking_) {
    e->body->advance_blends();
    if (e->controller != nullptr) e->controller->before_step(*e->body);
    e->body->refresh_faces();  // a stock world's solver does not: the faces must follow the cut before predictMotion
    e->stepped = true;
    ++e->ticks;
  }
  // A body that left the world since the last tick: its controller lets its workers sleep, and will not see a step
  // the body did not take.
  for (const auto& e : entries_)
    if (!e->seen) quiesce(*e);
  ++ticks_;
}

void TreeCutDriver::callback(btDynamicsWorld* world, btScalar) {
  TreeCutDriver* driver = nullptr;
  {
    std::lock_guard<std::mutex> lock(registry().mutex);
    for (const auto& [w, d] : registry().drivers)
      if (w == world) driver = d;
  }
  if (driver != nullptr) driver->pre_tick();
}

}  // namespace tcsb
