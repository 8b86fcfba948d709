// A camera for tests: ten metres in front of the origin on +z, looking at it, 90 degrees vertical field of view,
// 200 x 100 pixels, so the focal length is 50 pixels and one metre sideways at the origin is 5 pixels.
#pragma once

#include "view/camera.h"

namespace tcsb {

inline Camera camera_looking_at_origin() {
  Camera c;
  c.pose = {{0, 0, 10}, {0, 0, 0}};
  c.fov_deg = 90;
  c.width_px = 200;
  c.height_px = 100;
  return c;
}

}  // namespace tcsb
