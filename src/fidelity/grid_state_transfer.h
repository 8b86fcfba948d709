// A body's state carried onto another grid of the same cloth: what a switch of resolution does when it replaces one
// plain body by another (the fidelity pass's switch subject, the world pass's discrete levels of detail).
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/Core>

#include <vector>

#include "net/grid_resample.h"
#include "net/net.h"

namespace tcsb {

/// Sets the unpinned nodes of `to` (a plain body built from `to_net`) to the positions and velocities of `from` (a
/// plain body on grid `from_grid` spanning the same rectangle), bilinearly resampled; its pinned nodes stay where it
/// was built, at rest, as the old grid's are. Updates `to`'s bounds. The vectors are scratch, reused between calls.
void transfer_grid_state(const btSoftBody& from, GridSize from_grid, btSoftBody& to, const Net& to_net,
                         std::vector<Eigen::Vector3d>& x, std::vector<Eigen::Vector3d>& v,
                         std::vector<Eigen::Vector3d>& to_x, std::vector<Eigen::Vector3d>& to_v);

}  // namespace tcsb
