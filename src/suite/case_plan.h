// Case expansion and run order: a suite becomes cases (net x method x compression target), and the cases become a
// run order that interleaves methods and nets so ratios and fits are measured under the same machine conditions.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/case_pairing.h"
#include "suite/suite.h"

namespace tcsb {

/// One case: a configuration of the suite's axes, a net, a method, and (TC-SB, plain_equal) a compression target.
struct CaseKey {
  std::size_t net = 0;  ///< index into Suite::nets
  Method method = Method::kPlain;
  /// Node budget as a fraction of the initial count: TC-SB's target, or the budget a plain_equal grid is sized to;
  /// empty for the other methods.
  std::optional<double> compression;
  std::size_t configuration = 0;  ///< index into Suite::configurations (0 without axes)
};

/// Per configuration (in Suite::configurations order; one without axes), per net, in suite order: each method in
/// suite order; tcsb expands to one case per compression target (in suite order), plain_equal to one per target
/// below 1 (in suite order); plain and bullet_patch have no compression. Every configuration has the same cases.
std::vector<CaseKey> expand_cases(const Suite& suite);

/// The most cases a suite may expand to (configurations x nets x each net's cases): far more than any run can time,
/// few enough that expanding them takes milliseconds and tens of MB, not the machine's memory.
inline constexpr std::uint64_t kMaxCases = 1000000;

/// expand_cases(suite).size(), counted without expanding them (so a typing error of 10^8 cases costs nothing).
std::uint64_t case_count(const Suite& suite);

/// The position of case `case_index` (of expand_cases) among its configuration's cases: its index in the suite the
/// configuration makes alone (configuration_suite, suite/suite_axes.h), and so its seed there.
std::size_t index_in_configuration(const Suite& suite, std::size_t case_index);
/// The same, given cases_per_configuration(suite): for a loop over the cases, which would otherwise copy the suite and
/// expand its cases once per case.
std::size_t index_in_configuration(std::size_t per_configuration, std::size_t case_index);
/// How many cases each configuration of the suite has (all have the same).
std::size_t cases_per_configuration(const Suite& suite);

/// One repetition of one case, in run order.
struct PlannedRun {
  std::size_t case_index = 0;  ///< index into the expand_cases() result
  int repetition = 0;          ///< 0-based
};

/// Run order, repetition-major: each repetition runs every case once, net by net with a net's cases together in
/// suite order (plain, TC-SB, ... paired close in time for ratios; with axes, each configuration's cases of the net
/// together, configuration after configuration), and the net that starts a repetition rotates.
/// Every net is thus measured throughout the run, so cross-net fits see the same machine conditions for all nets.
std::vector<PlannedRun> interleaved_plan(const Suite& suite, const std::vector<CaseKey>& cases);

/// The seed of a case, the same for each of its repetitions: suite.seed x 1000003 + the case's index. With axes,
/// `suite` is the case's configuration_suite() and the index its index_in_configuration(), so a case draws the same
/// seed as in its configuration run alone.
std::uint64_t case_seed(const Suite& suite, std::size_t case_index);

/// A case's name in reports, e.g. "n65/plain", "n65/tcsb@0.75", "n65/tcsb@1.0", "n65/plain_equal@0.3"; with axes
/// its configuration follows in brackets, "n65/tcsb@0.75[piterations=8,blend_steps=4]", so every label is distinct.
std::string case_label(const Suite& suite, const CaseKey& key);

}  // namespace tcsb
