#include "gate/same_process.h"

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace tcsb {
namespace {

/// One timed repetition as measured: its case (label, configuration), number and mean step time. Two processes
/// never time a repetition to the same double; one process's repetition keeps its number and time in every file it
/// reaches (a copy, a shard, the result merged from the shards).
using RepetitionKey = std::tuple<std::string, std::string, int, double>;

std::optional<RepetitionKey> key_of(const CaseView& c, const RepetitionView& r) {
  if (!r.mean_step_ms) return std::nullopt;  // untimed (diverged): proves nothing
  return RepetitionKey{c.label, c.configuration, r.repetition, *r.mean_step_ms};
}

/// Timed repetitions of `a`'s cases that `b` also has (by label and configuration).
std::size_t timed_in_shared_cases(const ResultView& a, const std::set<std::pair<std::string, std::string>>& b_cases) {
  std::size_t n = 0;
  for (const CaseView& c : a.cases) {
    if (!b_cases.contains({c.label, c.configuration})) continue;
    for (const RepetitionView& r : c.repetitions) n += r.mean_step_ms.has_value();
  }
  return n;
}

}  // namespace

std::string shared_measurement(const ResultView& a, const ResultView& b) {
  // Indexed: a run has thousands of cases and repetitions at most, and each is looked up once.
  std::set<RepetitionKey> of_b;
  std::set<std::pair<std::string, std::string>> cases_a, cases_b;
  for (const CaseView& c : b.cases) {
    cases_b.insert({c.label, c.configuration});
    for (const RepetitionView& r : c.repetitions)
      if (const std::optional<RepetitionKey> k = key_of(c, r)) of_b.insert(*k);
  }
  for (const CaseView& c : a.cases) cases_a.insert({c.label, c.configuration});
  std::size_t shared = 0, first_case_shared = 0;
  std::string first_case;
  for (const CaseView& c : a.cases) {
    std::size_t here = 0;
    for (const RepetitionView& r : c.repetitions)
      if (const std::optional<RepetitionKey> k = key_of(c, r); k && of_b.contains(*k)) ++here;
    if (here > 0 && first_case.empty()) {
      first_case = c.label;
      first_case_shared = here;
    }
    shared += here;
  }
  if (shared == 0) return "";
  // Not whole cases: a shard split by repetition holds some of each case's repetitions, the merged result all of
  // them. One repetition alike by chance (a rounded clock, thousands of them) is not a process, two are; one is
  // when it is all the smaller file could share.
  const std::size_t could = std::min(timed_in_shared_cases(a, cases_b), timed_in_shared_cases(b, cases_a));
  if (shared < 2 && shared < could) return "";
  return "case " + first_case + " has the same " + std::to_string(first_case_shared) + " repetition time(s), " +
         std::to_string(shared) + " in all";
}

}  // namespace tcsb
