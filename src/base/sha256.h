// SHA-256 (FIPS 180-4), written out here because the project links no crypto library. Used to fingerprint suite
// files so every result records exactly which suite produced it.
#pragma once

#include <string>
#include <string_view>

namespace tcsb {

/// SHA-256 of `bytes` as 64 lowercase hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace tcsb
