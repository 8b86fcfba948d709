// The document `tcsb frames` writes for a scene of many bodies: the world pass's frames (world/world_frames.h), for
// scripts/render-figures.py --animate (the street fly-by).
#pragma once

#include <nlohmann/json.hpp>

#include "run/context.h"
#include "suite/suite.h"
#include "world/world_frames.h"

namespace tcsb {

/// Version of the world frames layout that scripts/render-figures.py reads. 1: the first.
inline constexpr int kWorldFramesSchemaVersion = 1;

/// frames_header() with "kind": "world_frames", then "compression", "camera" (camera_lens_json), "bodies": [{net,
/// width, height}] in scene order, "methods": [{method, status, diverged_step, diverged_reason, mean_nodes}] (TC-SB,
/// then discrete_lod), "frames": [{step, camera (camera_pose_json), scenes: [{method, nodes, bodies: [{xyz,
/// levels}]}]}], a frame's scenes in "methods" order. A body's xyz is its grid points row-major, flat (x, y, z, x, ...;
/// metres, y up, rounded to 1 mm); levels are one per grid point (WorldStepView::levels).
nlohmann::ordered_json world_frames_json(const Suite& suite, const Context& context, const WorldFrames& frames);

}  // namespace tcsb
