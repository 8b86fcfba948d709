#include "case/instruction_meter.h"

#include <string>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define TCSB_HAVE_CALLGRIND 1
#else
#define TCSB_HAVE_CALLGRIND 0
#endif

namespace tcsb {
namespace {

/// Callgrind writes one file per process, so the dumps are numbered per process, across every meter.
std::uint64_t next_dump = 0;

}  // namespace

void InstructionMeter::begin_step() {
  active_ = true;
#if TCSB_HAVE_CALLGRIND
  CALLGRIND_ZERO_STATS;
#endif
}

void InstructionMeter::end_part(StepPart part) {
  if (!active_) return;
  const std::uint64_t dump = next_dump++;
  parts_.push_back({dump, part});
#if TCSB_HAVE_CALLGRIND
  const std::string description = kMeterDumpPrefix + std::to_string(dump);
  CALLGRIND_DUMP_STATS_AT(description.c_str());
#endif
}

bool instruction_meter_available() { return TCSB_HAVE_CALLGRIND == 1; }

bool running_on_valgrind() {
#if TCSB_HAVE_CALLGRIND
  return RUNNING_ON_VALGRIND > 0;
#else
  return false;
#endif
}

}  // namespace tcsb
