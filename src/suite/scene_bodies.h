// The bodies of a scene of many (the suite's scene.bodies): each one of the suite's nets placed where it stands, and
// the checks such a scene must pass before anything runs. The world pass (world/world_runner.h) builds its bodies
// from scene_body_nets().
#pragma once

#include <string>
#include <vector>

#include "net/net_spec.h"
#include "suite/suite.h"
#include "suite/suite_fields.h"

namespace tcsb {

/// Whether `suite` is a scene of many bodies: then its run is the world pass.
inline bool is_world_suite(const Suite& suite) { return !suite.scene.bodies.empty(); }

/// The suite's net of that name, or nullptr.
const NetSpec* net_named(const Suite& suite, const std::string& name);

/// Each body's net, in scene order: the named net's spec with its rest rectangle centred on the body's position
/// (x, z) at the position's height. Throws std::invalid_argument for a name the suite has no net of (the parser has
/// refused it already).
std::vector<NetSpec> scene_body_nets(const Suite& suite);

/// Refuses, naming the field: a body naming no net of the suite, bodies of different nets (discrete LOD's levels are
/// fitted for one net's grids), two bodies whose rest rectangles overlap (at heights closer than the contact margin),
/// a scene of many bodies without a camera or, with more than one body, with fewer than two camera keyframes (the
/// camera must move along them), and feedback.budget_scope "world" without a TC-SB body to share the budget.
void check_scene_bodies(const suite_fields::Reader& r, const Suite& suite);

}  // namespace tcsb
