// Which cases of a run a claim is measured from, so that a claim the run could not decide can be given more
// repetitions of exactly those cases (and of nothing else).
#pragma once

#include <cstddef>
#include <vector>

#include "run/run_result.h"

namespace tcsb {

/// The cases behind a claim, on every net of the suite (the paper's claims average or fit over the whole test set).
struct ClaimScope {
  bool plain = false;                     ///< plain Bullet's cases (the baseline of a ratio)
  std::vector<double> tcsb_targets = {};  ///< TC-SB cases at these compression targets
  bool every_tcsb = false;                ///< every TC-SB case, whatever its target (fits over the test set, Table 1)
  bool operations = false;                ///< the operation samples of those TC-SB cases (Table 1)
  /// plain_equal cases at these compression targets (the project's equal-node-count targets).
  std::vector<double> equal_plain_targets = {};
};

/// The union of two scopes.
ClaimScope merged(const ClaimScope& a, const ClaimScope& b);

/// Indices of the cases in `scope`, in case order, plus the plain case of every net with a TC-SB case in it: a
/// net's TC-SB cases always run beside its plain baseline, as in the run itself, so ratios stay paired.
std::vector<std::size_t> cases_in_scope(const RunResult& result, const ClaimScope& scope);

/// Whether every case in `cases` is among `ran`.
bool all_among(const std::vector<std::size_t>& cases, const std::vector<std::size_t>& ran);

}  // namespace tcsb
