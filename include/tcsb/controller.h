// Public API: the feedback controller that keeps a TcSoftBody near its node budget.
//
// make_controller(settings, target_nodes, seed) gives the controller of the paper's Figure 1: each step it rates
// the cut's blocks by their motion (the BSWDF saliency) and begins refine and coarse operations to hold the budget.
// The per-step order is fixed:
//
//   body.advance_blends();            // blends move on; finished operations end
//   controller->before_step(body);    // new operations begin
//   body.simulate_step(dt);           // one Bullet step
//   controller->after_step(body);     // a parallel controller snapshots the state for its worker
//
// In a btSoftRigidDynamicsWorld that the application steps with stepSimulation, a TreeCutDriver (one per world, for
// every TC-SB body in it) does the same around every internal step from the world's pre-tick callback:
// examples/drape_tcsb.cpp. A running controller takes a new budget and camera (set_budget, set_spectator) at its next
// step boundary: examples/client_tcsb.cpp; one budget for all of a world's bodies, TreeCutDriver::set_world_budget
// (world_budget.h). The settings to start from per kind of scene: presets.h, docs/library.md.
//
// With settings.view the saliency sees through a camera (the BSWDF's view terms: motion on the image, nothing out of
// view kept fine): pass make_controller a Spectator (tcsb/view.h: the camera, fixed or along keyframes, and the
// step length), as make_controller(settings, target_nodes, seed, Spectator{camera, dt}).
#pragma once

#include "feedback/controller.h"         // IWYU pragma: export
#include "feedback/feedback_settings.h"  // IWYU pragma: export
#include "feedback/presets.h"            // IWYU pragma: export
#include "feedback/tree_cut_driver.h"    // IWYU pragma: export
#include "feedback/world_budget.h"       // IWYU pragma: export
