#include "gate/same_process.h"

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace tcsb {
namespace {

/// What a case measured: each repetition's number, status and mean step time, in file order.
using Measurement = std::vector<std::tuple<int, std::string, std::optional<double>>>;

Measurement measurement_of(const CaseView& c) {
  Measurement m;
  for (const RepetitionView& r : c.repetitions) m.emplace_back(r.repetition, r.status, r.mean_step_ms);
  return m;
}

std::size_t timed(const CaseView& c) {
  std::size_t n = 0;
  for (const RepetitionView& r : c.repetitions) n += r.mean_step_ms.has_value();
  return n;
}

}  // namespace

std::string shared_measurement(const ResultView& a, const ResultView& b) {
  // Indexed by label and configuration: a run has thousands of cases at most, and each is looked up once.
  std::map<std::pair<std::string, std::string>, const CaseView*> of_b;
  for (const CaseView& c : b.cases) of_b.emplace(std::make_pair(c.label, c.configuration), &c);
  for (const CaseView& c : a.cases) {
    const auto it = of_b.find({c.label, c.configuration});
    if (it == of_b.end() || timed(c) == 0) continue;
    if (measurement_of(c) == measurement_of(*it->second))
      return "case " + c.label + " has the same " + std::to_string(timed(c)) + " repetition time(s)";
  }
  return "";
}

}  // namespace tcsb
