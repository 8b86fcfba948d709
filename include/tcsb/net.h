// Public API: the cloth net and its level-of-detail tree.
//
// A Net is built from a NetSpec (grid size, extent, mass, pinned corners, which links) and owns the regular grid,
// its links and the LOD tree whose cuts a TcSoftBody simulates. Build it once and share it: bodies hold a
// std::shared_ptr<const Net>.
#pragma once

#include "net/lod_tree.h"  // IWYU pragma: export
#include "net/net.h"       // IWYU pragma: export
#include "net/net_spec.h"  // IWYU pragma: export
