// The instruction-count gate: two runs measured with `--measure instructions` (counted by callgrind, the same in
// every run of a build) compared case by case. There is no noise to test against, so a count that grows by more
// than the threshold is a decided regression; the functions whose own instructions grew most say where. Pure.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "result/result_view.h"

namespace tcsb {

/// A function whose own instructions differ between the runs.
struct FunctionShift {
  std::string name;
  std::int64_t base = 0, next = 0;  ///< own instructions; 0 where the function is not among a run's listed ones
  bool listed_in_both = true;       ///< false: absent from one run's list (below its kept functions, or not run)
};

/// One case's counts in both runs, and what the gate concludes.
struct InstructionDecision {
  std::string case_label;
  InstructionsView base, next;        ///< the counts as recorded (functions included)
  std::optional<double> change;       ///< next.total / base.total - 1; nullopt when base.total is 0
  bool regressed = false;             ///< change > threshold, or instructions where the base had none
  bool improved = false;              ///< -change > threshold
  std::vector<FunctionShift> shifts;  ///< the largest increases first, at most kShiftsShown (regressions only)
};

/// Functions named per regressed case.
inline constexpr std::size_t kShiftsShown = 5;

/// Decides every pair of cases (base, next) that both carry counts: regressed when the total count grows by more than
/// `threshold` (a fraction, >= 0). Throws std::invalid_argument on a negative or non-finite threshold.
InstructionDecision decide_instructions(const std::string& label, const InstructionsView& base,
                                        const InstructionsView& next, double threshold);

}  // namespace tcsb
