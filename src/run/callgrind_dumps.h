// Reading the meter's dumps back from callgrind's output file (one file, --combine-dumps=yes): each dump's
// instruction count and its functions' own (self) instructions. The format is callgrind's documented text format
// ("Callgrind Format Specification" in Valgrind's manual); only what the meter needs is read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tcsb {

/// A callgrind file that cannot be read, or lacks a dump the run took. what() is one line naming the file.
class CallgrindFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One dump: what ran between it and the previous dump (or a zeroing of the counters).
struct CallgrindDump {
  std::uint64_t instructions = 0;  ///< the dump's summary (event Ir)
  /// Own instructions per function (indices into MeterDumps::names), excluding what the functions it called ran.
  std::vector<std::pair<std::uint32_t, std::uint64_t>> functions;
};

/// The meter's dumps of one process, by number (InstructionMeter's MeteredPart::dump).
struct MeterDumps {
  std::vector<std::string> names;                   ///< function names as callgrind wrote them
  std::vector<std::optional<CallgrindDump>> dumps;  ///< index: the dump's number; nullopt: not in the file
};

/// Parses callgrind's text output: the dumps whose description is "tcsb-part N" (kMeterDumpPrefix). Other dumps (the
/// one at program end) are skipped. Throws CallgrindFileError when the file cannot be read or a line is malformed.
MeterDumps parse_meter_dumps(std::istream& in, const std::string& file);

/// parse_meter_dumps of a file.
MeterDumps read_meter_dumps(const std::filesystem::path& file);

}  // namespace tcsb
