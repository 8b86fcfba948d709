// OpKind: the four TreeCut operations, as the cut listener hears of them and operation samples are counted by.
#pragma once

#include <cstdint>

namespace tcsb {

/// The four TreeCut operations (paper §3.3–3.4).
enum class OpKind : std::uint8_t { kRefine, kEndRefine, kCoarse, kEndCoarse };
inline constexpr int kOpKindCount = 4;

/// Name used in reports: "refine", "end-refine", "coarse", "end-coarse".
inline const char* op_kind_name(OpKind kind) {
  switch (kind) {
    case OpKind::kRefine: return "refine";
    case OpKind::kEndRefine: return "end-refine";
    case OpKind::kCoarse: return "coarse";
    case OpKind::kEndCoarse: return "end-coarse";
  }
  return "?";
}

}  // namespace tcsb
