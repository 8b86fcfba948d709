// Public API: the spectator — the camera the feedback's view terms see the cloth through.
//
// A Camera is a pinhole (position, target, up, vertical field of view, image size), fixed or moving along keyframes;
// a Spectator is the camera with the step length, given to make_controller when settings.view is on
// (validate_spectator says what it refuses). ScreenProjection is the camera at one moment: where a point appears on
// the image, whether it is in view, how fast a motion crosses it — for an application that wants to see the cloth as
// the controller does.
#pragma once

#include "view/camera.h"             // IWYU pragma: export
#include "view/keyframe_path.h"      // IWYU pragma: export
#include "view/screen_projection.h"  // IWYU pragma: export
