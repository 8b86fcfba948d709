// tcsb: the TreeCut soft body of "Perception-influenced Animation" (Schiffner & Kroemker) inside Bullet 3.24.
// One include for the whole public API; examples/hello_tcsb.cpp shows it in use. With CMake:
//
//   find_package(tcsb REQUIRED)
//   target_link_libraries(app PRIVATE tcsb::tcsb)
#pragma once

#include "tcsb/controller.h"   // IWYU pragma: export
#include "tcsb/net.h"          // IWYU pragma: export
#include "tcsb/tc_softbody.h"  // IWYU pragma: export
#include "tcsb/view.h"         // IWYU pragma: export
