// The suite's "scene" block: colliders (static, moving or keyframed), the contact settings, wind, pins that move
// and the camera, each checked before anything runs. Its own file: the suite reader stays the reader of the suite's
// shape.
#pragma once

#include "scene/scene_settings.h"
#include "suite/suite_fields.h"

namespace tcsb {

/// Reads the object `j` at "scene". Throws InputError naming the field.
SceneSettings parse_scene(const suite_fields::Reader& r, const nlohmann::json& j);

}  // namespace tcsb
