// tcsb: the TreeCut soft body of "Perception-influenced Animation" (Schiffner & Kroemker) inside Bullet 3.24.
// One include for the whole public API; examples/hello_tcsb.cpp shows it in use. The API is five headers, each of
// which compiles alone (docs/library.md): net.h (the net and its LOD tree), tc_softbody.h (the body, its settings and
// the solver a world steps it with), cut_listener.h (the cut's changes), controller.h (the controller, the driver and
// the presets), view.h (the spectator's camera). They reach no implementation header of the library. With CMake:
//
//   find_package(tcsb REQUIRED)
//   target_link_libraries(app PRIVATE tcsb::tcsb)
#pragma once

#include "tcsb/controller.h"    // IWYU pragma: export
#include "tcsb/cut_listener.h"  // IWYU pragma: export
#include "tcsb/net.h"           // IWYU pragma: export
#include "tcsb/tc_softbody.h"   // IWYU pragma: export
#include "tcsb/view.h"          // IWYU pragma: export
