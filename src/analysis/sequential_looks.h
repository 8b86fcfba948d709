// Repeated looks at the same claims: after each batch of extra repetitions the claims are judged again, and every
// look is another chance to decide wrongly. Each look therefore spends a share of the error rate, alpha_k =
// alpha / 2^k at the k-th look (k = 1, 2, ...), so the chance of a wrong verdict over all looks stays below alpha
// (sum of alpha / 2^k < alpha). docs/methodology.md explains the choice.
#pragma once

namespace tcsb {

/// The error rate of the whole sequence of looks, per claim.
inline constexpr double kSequentialAlpha = 0.05;

/// Bootstrap replicates each tail of an interval must rest on: fewer and its end is one or two extreme values.
inline constexpr int kReplicatesPerTail = 10;

/// The error rate spent at look `look` (1-based): alpha / 2^look. Throws std::invalid_argument unless look >= 1
/// and 0 < alpha < 1.
double look_alpha(double alpha, int look);

/// The confidence of the central interval judged at look `look`: 1 - 2 look_alpha. Its lower and upper ends are
/// each a one-sided test at level look_alpha; "pass" and "fail" each need one of them (an equivalence claim needs
/// both ends inside its band: two one-sided tests, the same interval). Look 1 at alpha 0.05 gives 95 %.
double look_confidence(double alpha, int look);

/// Bootstrap resamples for look `look`: ceil(kReplicatesPerTail / look_alpha), so each tail of the interval rests
/// on at least kReplicatesPerTail replicates (400 at look 1, doubling with every look).
int look_resamples(double alpha, int look);

}  // namespace tcsb
