// Hand-made native result documents for the comparison tests: only the fields ResultView reads, every number
// chosen so the expected outcome is obvious. No Bullet, no runs.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tcsb::testing {

using ojson = nlohmann::ordered_json;

/// A repetition with the given mean step time and deterministic quantities.
inline ojson repetition_doc(int index, double ms, double nodes, const std::string& hash = "h") {
  return {{"repetition", index},        {"status", "ok"},      {"diverged_step", nullptr},
          {"mean_step_ms", ms},         {"mean_nodes", nodes}, {"mean_links", 2 * nodes},
          {"mean_interpolations", 1.5}, {"operations", 7},     {"final_state_hash", hash + std::to_string(index)}};
}

/// A case whose repetitions take `ms[r]` each.
inline ojson case_doc(const std::string& net, const std::string& method, double nodes, const std::vector<double>& ms) {
  ojson reps = ojson::array();
  for (std::size_t r = 0; r < ms.size(); ++r) reps.push_back(repetition_doc(static_cast<int>(r), ms[r], nodes));
  const std::string label = net + "/" + method;
  return {{"label", label},
          {"net", net},
          {"method", method == "plain" ? "plain" : "tcsb"},
          {"compression", nullptr},
          {"status", "ok"},
          {"mean_nodes", nodes},
          {"mean_links", 2 * nodes},
          {"mean_interpolations", 1.5},
          {"step_ms", {{"median", ms.empty() ? 0.0 : ms[ms.size() / 2]}, {"stddev", 0.0}, {"cv", 0.0}}},
          {"repetitions", std::move(reps)}};
}

/// `n` copies of `value`, with a small spread so the U test has no ties.
inline std::vector<double> around(double value, int n = 9) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(value * (1.0 + 0.002 * i));
  return out;
}

/// A two-net run: per net a plain case (1 ms) and a TC-SB case ("tcsb@0.5", 0.5 ms), nine repetitions each.
inline ojson result_doc(int repetitions = 9) {
  ojson cases = ojson::array();
  for (const char* net : {"n9", "n17"}) {
    cases.push_back(case_doc(net, "plain", 81, around(1.0, repetitions)));
    cases.push_back(case_doc(net, "tcsb@0.5", 40, around(0.5, repetitions)));
  }
  return {{"schema_version", 2},
          {"tool", "tcsb"},
          {"context",
           {{"cpu_model", "Test CPU"},
            {"cores", 2},
            {"build_type", "Release"},
            {"bullet_version", "3.24"},
            {"git_commit", "abc"},
            {"warnings", ojson::array()},
            {"seed", 1}}},
          {"suite",
           {{"name", "tiny"},
            {"path", "/somewhere/tiny.json"},
            {"sha256", std::string(64, 'a')},
            {"steps", 20},
            {"repetitions", repetitions},
            {"feedback", {{"max_step_ms", 0.0}}},
            {"methods", {"plain", "tcsb"}}}},
          {"cases", std::move(cases)}};
}

/// Multiplies every repetition's mean step time of case `index` by `factor`.
inline void scale_case(ojson& doc, std::size_t index, double factor) {
  for (ojson& r : doc["cases"][index]["repetitions"]) r["mean_step_ms"] = r["mean_step_ms"].get<double>() * factor;
}

}  // namespace tcsb::testing
