// Presets: the recommended settings for the kinds of scene a game puts TC-SB in, one function per kind, each the
// settings of the shipped suite that measures that kind of scene (docs/library.md; a test checks each against its
// suite file, so the library, the suites and the docs cannot drift apart).
#pragma once

#include "../feedback/feedback_settings.h"
#include "../net/lod_tree.h"
#include "../softbody/solver_settings.h"
#include "../softbody/tc_settings.h"

namespace tcsb {

/// What a kind of scene asks of a body: the solver, TC-SB's operations, the feedback, and how the net's LOD tree
/// rests (NetSpec::lod_rest: RestPlacement::kVertex, which TcSettings::masses = Masses::kCut needs).
struct Preset {
  SolverSettings solver;
  TcSettings tcsb;
  FeedbackSettings feedback;
  RestPlacement lod_rest = RestPlacement::kVertex;
};

/// A cloth hanging from pins, swinging (suites/converged.json): 32 position iterations, hanging interfaces, masses
/// that follow the cut, links in a plain body's order; the feedback evaluated every 4 steps on a worker thread,
/// charging the level boundaries a refine or coarse would add, more near the pins.
Preset hanging_cloth_preset();
/// A sheet dropped onto colliders (suites/drape.json): 16 iterations, contact as an animation feature (0.1).
Preset drape_preset();
/// A flag in wind (suites/flag.json): 16 iterations, evaluated on the simulation thread. The body needs faces
/// (TcSoftBody::enable_faces) for Bullet's aerodynamic model, and the wind is Bullet's: m_cfg.aeromodel, kLF, kDG and
/// setWindVelocity on the body (suites/flag.json: V_TwoSidedLiftDrag, 6 m/s, lift 0.2, drag 0.5).
Preset flag_preset();
/// A close-up camera on a hanging cloth (suites/viewer-corner.json): the hanging cloth's settings with the BSWDF's
/// view terms; a quiet node in view keeps almost nothing for its size alone (view_static_share 0.001), so motion
/// decides what the camera sees in detail. make_controller then needs a Spectator.
Preset close_up_preset();

}  // namespace tcsb
