#include "report/gate_summary_json.h"

namespace tcsb {

nlohmann::ordered_json gate_summary_json(const GateOutcome& o, int exit_code, const std::string& base_file,
                                         const std::string& next_file) {
  nlohmann::ordered_json j;
  j["measure"] = o.comparison.measure;
  j["verdict"] = verdict_name(o.verdict());
  j["exit_code"] = exit_code;
  j["behaviour_changes"] = o.comparison.changes.size();
  j["regressions"] = o.regressions;
  j["undecided"] = o.undecided;
  j["gated"] = o.gated_metrics;  // timing metrics, or cases' instruction counts
  j["more_repetitions"] = o.undecided > 0 ? nlohmann::ordered_json(o.more_repetitions()) : nullptr;
  j["threshold"] = o.settings.threshold;
  j["alpha"] = o.counts ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(o.settings.alpha);
  j["base"] = base_file;
  j["new"] = next_file;
  // A merged result's intervals resample its processes (shards) first: how many each side's widest interval pooled.
  const auto [base_processes, next_processes] = o.processes();
  j["processes"] = {{"base", base_processes}, {"new", next_processes}};
  return j;
}

}  // namespace tcsb
