// The document `tcsb frames` writes: the paper's Figure 6 as data (fidelity/figure_frames.h), for
// scripts/render-figures.py.
#pragma once

#include <nlohmann/json.hpp>

#include "fidelity/figure_frames.h"
#include "run/context.h"
#include "suite/suite.h"

namespace tcsb {

/// Version of the frames layout that scripts/render-figures.py reads. 1: the first, with a context block.
inline constexpr int kFramesSchemaVersion = 1;

/// {"schema_version", "tool": "tcsb", "kind": "frames", "context" (context_json), "suite" (suite_json), "dt", "net":
/// {name, width, height}, "compression", "status", "diverged_step", "diverged_reason", "frames": [{step,
/// interpolations, plain, tcsb_surface, tcsb_nodes, tcsb_links}]}. Points are [x, y, z] in metres rounded to 10 um
/// (y up); plain and tcsb_surface hold one point per grid node, row-major; tcsb_links are [a, b, role] with a and b
/// indices into tcsb_nodes and role a link_role_name(). "kind" tells it from a run result, which has none.
nlohmann::ordered_json frames_json(const Suite& suite, const Context& context, const FigureFrames& frames);

/// What every frames document opens with: {"schema_version", "tool": "tcsb", "kind", "context", "suite", "dt"}.
nlohmann::ordered_json frames_header(const Suite& suite, const Context& context, int schema_version, const char* kind);

/// The camera's lens and image: {"up", "fov_deg", "image": [width, height]}.
nlohmann::ordered_json camera_lens_json(const Camera& camera);

/// Where the camera stands after `steps` steps of `suite`: {"position", "target"}.
nlohmann::ordered_json camera_pose_json(const Suite& suite, int steps);

}  // namespace tcsb
