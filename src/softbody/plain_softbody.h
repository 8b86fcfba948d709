// The baselines: stock btSoftBody built from the net, and stock btSoftBodyHelpers::CreatePatch of the same grid.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <memory>

#include "../net/net.h"
#include "../softbody/solver_settings.h"

namespace tcsb {

/// Stock btSoftBody whose nodes and links are exactly the net's finest level, in the net's canonical link order
/// (row-major; for each node its +x link then its +z link — CreatePatch's order). No faces: the paper's model needs
/// only nodes and links, and TC-SB has none either. Under the compliant material (SolverSettings::model) a
/// CompliantSoftBody with the membrane rule's constants, stepped in small steps; else stock Bullet.
std::unique_ptr<btSoftBody> make_plain_softbody(btSoftBodyWorldInfo& world, const Net& net,
                                                const SolverSettings& settings);

/// Stock btSoftBodyHelpers::CreatePatch of the same grid, pins (corners through CreatePatch, any others by zero
/// inverse mass) and total mass, with the same solver settings and
/// its faces dropped (no compared body has faces). Used only to show the plain baseline is not handicapped. The net
/// must have structural links only (CreatePatch makes no shear or bend links).
std::unique_ptr<btSoftBody> make_bullet_patch(btSoftBodyWorldInfo& world, const Net& net,
                                              const SolverSettings& settings);

}  // namespace tcsb
