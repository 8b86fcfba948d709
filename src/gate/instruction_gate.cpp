#include "gate/instruction_gate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "analysis/relative_change.h"

namespace tcsb {
namespace {

std::vector<FunctionShift> largest_increases(const InstructionsView& base, const InstructionsView& next) {
  std::map<std::string, FunctionShift> by_name;
  for (const auto& [name, count] : base.functions) {
    FunctionShift& s = by_name[name];
    s.name = name;
    s.base = count;
    s.listed_in_both = false;
  }
  for (const auto& [name, count] : next.functions) {
    FunctionShift& s = by_name[name];
    s.listed_in_both = !s.name.empty();
    s.name = name;
    s.next = count;
  }
  std::vector<FunctionShift> shifts;
  for (auto& [name, s] : by_name)
    if (s.next > s.base) shifts.push_back(std::move(s));
  // Largest increase first; equal ones by name (the map's order), so the summary is the same in every run.
  std::stable_sort(shifts.begin(), shifts.end(),
                   [](const FunctionShift& a, const FunctionShift& b) { return a.next - a.base > b.next - b.base; });
  if (shifts.size() > kShiftsShown) shifts.resize(kShiftsShown);
  return shifts;
}

}  // namespace

InstructionDecision decide_instructions(const std::string& label, const InstructionsView& base,
                                        const InstructionsView& next, double threshold) {
  if (!(threshold >= 0.0) || !std::isfinite(threshold))
    throw std::invalid_argument("decide_instructions: threshold must be a finite number >= 0");
  InstructionDecision d;
  d.case_label = label;
  d.base = base;
  d.next = next;
  d.change = safe_ratio(static_cast<double>(next.total - base.total), static_cast<double>(base.total));
  if (d.change) {
    d.regressed = *d.change > threshold;
    d.improved = -*d.change > threshold;
  } else {
    d.regressed = next.total > 0;  // work where the base counted none
  }
  if (d.regressed) d.shifts = largest_increases(base, next);
  d.base.functions.clear();  // the shifts say what the reader needs of them
  d.next.functions.clear();
  return d;
}

}  // namespace tcsb
