#include "run/instruction_counts.h"

#include <algorithm>
#include <unordered_map>

namespace tcsb {

const char* measure_name(Measure measure) { return measure == Measure::kInstructions ? "instructions" : "time"; }

void attach_instruction_counts(RunResult& result, const MeterDumps& dumps, const std::string& file) {
  for (CaseResult& c : result.cases) {
    InstructionCount sum;
    std::unordered_map<std::uint32_t, std::uint64_t> functions;
    for (RepetitionResult& r : c.repetitions) {
      InstructionCount count;
      for (const MeteredPart& p : r.metered) {
        if (p.dump >= dumps.dumps.size() || !dumps.dumps[p.dump]) {
          throw CallgrindFileError(file + ": dump " + std::to_string(p.dump) + " (case " + c.label + ", repetition " +
                                   std::to_string(r.repetition) + ") is missing");
        }
        const CallgrindDump& dump = *dumps.dumps[p.dump];
        (p.part == StepPart::kOwn ? count.own : count.bullet) += dump.instructions;
        if (r.status != "ok") continue;
        for (const auto& [name, cost] : dump.functions) functions[name] += cost;
      }
      r.metered.clear();
      r.instructions = count;
      if (r.status != "ok") continue;
      sum.own += count.own;
      sum.bullet += count.bullet;
    }
    c.instructions = sum;
    std::vector<FunctionCount> ranked;
    for (const auto& [name, cost] : functions) ranked.push_back({dumps.names[name], cost});
    // Most first; equal counts by name, so the file does not depend on the hash map's order.
    std::sort(ranked.begin(), ranked.end(), [](const FunctionCount& a, const FunctionCount& b) {
      return a.instructions != b.instructions ? a.instructions > b.instructions : a.name < b.name;
    });
    if (ranked.size() > kFunctionsKept) ranked.resize(kFunctionsKept);
    c.functions = std::move(ranked);
  }
}

}  // namespace tcsb
