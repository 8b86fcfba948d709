// InstructionMeter: counts a timed step's instructions in parts — TC-SB's own work and Bullet's solve — under
// Valgrind's callgrind (`tcsb run --measure instructions`). Callgrind cannot hand a count back to the program, so each
// part ends with a dump of the counters (CALLGRIND_DUMP_STATS_AT) that names it by a sequence number, and the counts
// are read from the dump file after the run (run/callgrind_dumps.h). Outside callgrind the requests do nothing.
#pragma once

#include <cstdint>
#include <vector>

namespace tcsb {

/// What a part of a step counts.
enum class StepPart : std::uint8_t {
  kOwn,     ///< TC-SB's own work: blends, the feedback stage and the operations it begins and ends
  kBullet,  ///< Bullet's step of the world (predict, solve, integrate)
};

/// One part of one timed step: the dump that holds its count.
struct MeteredPart {
  std::uint64_t dump = 0;  ///< its number: the process's dumps are numbered 0, 1, ... in the order they were taken
  StepPart part = StepPart::kOwn;
};

/// The meter of one repetition. The runner brackets each timed step (begin_step / end_step); the body ends each part
/// of it (end_part) where the part's work ends. Parts ended outside a bracketed step are not counted, so warm-up steps
/// and untimed steps cost only a branch.
class InstructionMeter {
 public:
  /// A timed step begins: the counters restart from zero (whatever ran since the last dump is not a part).
  void begin_step();
  /// The work of `part` since the last dump (or begin_step) ends here: dumped and numbered.
  void end_part(StepPart part);
  /// The timed step ends.
  void end_step() { active_ = false; }
  /// Every part this meter dumped, in order.
  const std::vector<MeteredPart>& parts() const { return parts_; }

 private:
  std::vector<MeteredPart> parts_;
  bool active_ = false;
};

/// The description a dump of `dump` carries in callgrind's file ("desc: Trigger: Client Request: ..."), so the reader
/// finds the part by its number whatever else dumped in between.
inline constexpr const char* kMeterDumpPrefix = "tcsb-part ";

/// This build can talk to callgrind (it was compiled with valgrind/callgrind.h, Debian's valgrind package).
bool instruction_meter_available();

/// The program runs under Valgrind (any tool).
bool running_on_valgrind();

}  // namespace tcsb
