// State hash: a deterministic fingerprint of a body's final state, so CI can gate on "same behaviour" exactly.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <string>

namespace tcsb {

/// FNV-1a (64 bit) over the node count, link count and every node position's bytes, as 16 hex digits.
std::string state_hash(const btSoftBody& body);

}  // namespace tcsb
