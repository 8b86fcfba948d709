// Suite memory estimate: how many bytes a run of a suite needs at most, so a suite too large for this machine is
// rejected while it is read, in milliseconds, instead of being killed by the kernel mid-run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "harness/suite.h"

namespace tcsb {

/// Bytes a run of this suite needs at most for its largest net (all methods' bodies alive at once), an estimate
/// used to reject suites that would not fit.
std::uint64_t estimate_peak_bytes(const Suite& suite);

/// A suite whose largest net would not fit: which net, and the figures for the error message.
struct MemoryShortfall {
  std::size_t net = 0;   ///< index into suite.nets of the net with the largest peak
  double needed = 0;     ///< estimate_peak_bytes(suite)
  double usable = 0;     ///< 80 % of available: what a run may take
  double available = 0;  ///< MemAvailable of /proc/meminfo
};

/// The shortfall when the suite needs more than 80 % of this machine's available memory; nothing when it fits, or
/// when the machine does not say what is available.
std::optional<MemoryShortfall> memory_shortfall(const Suite& suite);

/// "12.3 MiB" or "1.5 GiB".
std::string format_bytes(double bytes);

}  // namespace tcsb
