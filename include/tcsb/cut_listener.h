// Public API: the listener — what an application hears of a TcSoftBody's cut as it changes.
//
// Derive from CutListener and give it to a body (TcSoftBody::set_cut_listener): cut_changed says which operation ran
// on which block (OpKind), arrays_reordered that Bullet's node and link arrays were put back in order. Bullet indices
// change then and nowhere else, so a render mesh or anything kept per simulated node is rebuilt there
// (examples/render_tcsb.cpp).
#pragma once

#include "softbody/cut_listener.h"  // IWYU pragma: export
#include "softbody/op_kind.h"       // IWYU pragma: export
