#include "run/out_of_memory.h"

#include <optional>

#include "base/memory_limits.h"
#include "suite/suite_memory.h"

namespace tcsb {

std::string out_of_memory_message(const std::string& what) {
  std::string message = what + ": out of memory: the suite is too large for this machine's memory limits";
  if (const std::optional<MemoryHeadroom> h = smallest_headroom(memory_headrooms()))
    message += " (headroom now under " + h->source + ": " + format_bytes(static_cast<double>(h->bytes)) + ")";
  return message + "; use smaller nets, fewer steps or fewer repetitions";
}

}  // namespace tcsb
