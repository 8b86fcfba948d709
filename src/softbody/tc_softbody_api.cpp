// TcSoftBody's public API: construction, and each call handed to the state behind it (tc_softbody_impl.h), where
// the work is done. One forward per call and none inside the operations or the per-step solve, which run on Impl.
#include <memory>
#include <string>
#include <utility>

#include "softbody/tc_softbody_impl.h"

namespace tcsb {

TcSoftBody::TcSoftBody(btSoftBodyWorldInfo& world, std::shared_ptr<const Net> net, const SolverSettings& solver,
                       const TcSettings& settings)
    : btSoftBody(&world, 0, nullptr, nullptr), impl_(std::make_unique<Impl>(*this, std::move(net), solver, settings)) {}

TcSoftBody::~TcSoftBody() {
  if (impl_->lifetime_ != nullptr) impl_->lifetime_->body_destroyed(*this);
}

void TcSoftBody::set_lifetime_listener(LifetimeListener* listener) { impl_->lifetime_ = listener; }
TcSoftBody::LifetimeListener* TcSoftBody::lifetime_listener() const { return impl_->lifetime_; }
const Net& TcSoftBody::net() const { return impl_->net(); }
const LodTree& TcSoftBody::tree() const { return impl_->tree(); }
const TcSettings& TcSoftBody::settings() const { return impl_->settings(); }
const SolverSettings& TcSoftBody::solver() const { return impl_->solver(); }
CutState TcSoftBody::state(TreeId id) const { return impl_->state(id); }
bool TcSoftBody::committed(TreeId id) const { return impl_->committed(id); }
int TcSoftBody::bullet_index(TreeId id) const { return impl_->bullet_index(id); }
TreeId TcSoftBody::tree_id(int index) const { return impl_->tree_id(index); }
std::span<const CutState> TcSoftBody::states() const { return impl_->states(); }
std::span<const std::int32_t> TcSoftBody::bullet_indices() const { return impl_->bullet_indices(); }
std::span<const TreeId> TcSoftBody::tree_ids() const { return impl_->tree_ids(); }
std::span<const CutLink> TcSoftBody::cut_links() const { return impl_->cut_links(); }
double TcSoftBody::simulated_mass(TreeId id) const { return impl_->simulated_mass(id); }
int TcSoftBody::committed_count() const { return impl_->committed_count(); }
int TcSoftBody::interpolations() const { return impl_->interpolations(); }
OpCheck TcSoftBody::can_refine(TreeId id) const { return impl_->can_refine(id); }
OpCheck TcSoftBody::can_coarsen(TreeId parent) const { return impl_->can_coarsen(parent); }
bool TcSoftBody::anchored(TreeId id) const { return impl_->anchored(id); }
void TcSoftBody::begin_refine(TreeId id) { impl_->begin_refine(id); }
void TcSoftBody::begin_coarse(TreeId parent) { impl_->begin_coarse(parent); }
int TcSoftBody::coarsen_to_level(int level) { return impl_->coarsen_to_level(level); }
void TcSoftBody::advance_blends(OrderSettling settling) { impl_->advance_blends(settling); }
void TcSoftBody::simulate_step(btScalar dt) { impl_->simulate_step(dt); }
void TcSoftBody::solve_constraints() { impl_->solve_constraints(); }
void TcSoftBody::move_pins(const btVector3& offset, btScalar dt) { impl_->move_pins(offset, dt); }
const btVector3& TcSoftBody::pin_offset() const { return impl_->pin_offset(); }
btVector3 TcSoftBody::pin_position(TreeId id) const { return impl_->pin_position(id); }
void TcSoftBody::enable_faces() { impl_->enable_faces(); }
bool TcSoftBody::faces_enabled() const { return impl_->faces_enabled(); }
void TcSoftBody::refresh_faces() { impl_->refresh_faces(); }
void TcSoftBody::set_cut_listener(CutListener* listener) { impl_->set_cut_listener(listener); }
void TcSoftBody::restore_order() { impl_->restore_order(); }
void TcSoftBody::settle_order() { impl_->settle_order(); }
Validation TcSoftBody::validate() const { return impl_->validate(); }
Eigen::Matrix<double, 3, 2> TcSoftBody::local_affine_fit(TreeId id) const { return impl_->local_affine_fit(id); }
Eigen::Vector3d TcSoftBody::linear_momentum() const { return impl_->linear_momentum(); }
double TcSoftBody::total_mass() const { return impl_->total_mass(); }

std::string Validation::summary() const {
  if (problems.empty()) return "ok";
  std::string s = std::to_string(problems.size()) + " problem(s): " + problems.front();
  return s;
}

}  // namespace tcsb
