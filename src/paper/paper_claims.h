// The paper's claims, checked against a run — each named after the table or figure it checks — and, separately,
// the stricter targets this project set itself.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "analysis/claim.h"
#include "paper/claim_scope.h"
#include "paper/paper_reference.h"
#include "paper/paper_tables.h"

namespace tcsb {

/// The R^2 Figure 5's line through every TC-SB case must reach (step_linear_tcsb).
inline constexpr double kLinearR2 = 0.95;
/// NoCompression's margin over plain Bullet's cost: the paper's TC-SB without compression ran at 0.909 x plain, i.e.
/// not slower, so the claim is non-inferiority — TC-SB's ratio at most 1 + this.
inline constexpr double kNoCompressionMargin = 0.03;
/// The id of the NoCompression claim.
inline constexpr const char* kNoCompressionClaimId = "tcsb_nocompression_vs_plain";
/// The id of the sanity line beside it (not a claim of the paper: reported, never gating).
inline constexpr const char* kNoCompressionSanityId = "sanity_nocompression_not_faster";

/// What the paper claims, as checks on our measurements (a failed one makes `tcsb reproduce` exit 1). All are
/// measured from repetitions and judged on their intervals:
///  - Table 2: TC-SB at 30 % and 75 % cost at most the paper's ratio to plain Bullet (4.80/11.09, 8.40/11.09);
///  - Table 2: TC-SB with nothing to compress is not slower than plain Bullet, ratio at most 1.03 (non-inferiority:
///    passes when the interval's upper end is <= 1.03, fails when its lower end is > 1.03);
///  - Figure 5: one line through every TC-SB case (all budgets, all nets) fits with R^2 >= kLinearR2
///    (`tcsb_fit`: step_fit_of_method(result, Method::kTcsb));
///  - Table 1: each operation costs at most the paper's mean complete time (`table1`: our Table 1).
/// Figure 4 (operations constant in time) is judged on deterministic work counts, appended by the caller.
std::vector<Claim> paper_claims(const PaperReference& paper, const std::vector<Table2Row>& table2,
                                const StepFit& tcsb_fit, const std::vector<Table1Row>& table1);

/// This project's own, stricter speed targets (reported with verdicts, not gating the exit code), measured from
/// repetitions: at 30 %, <= 0.40 x plain and <= 1.10 x the node ratio (feedback, operations and blending under
/// 10 %); at 75 %, <= 0.80 x plain; and, when the run has plain_equal cases at 30 % or 75 %, TC-SB there costs at
/// most 1.10 x plain_equal (`target_30_vs_equal_plain`, `target_75_vs_equal_plain`).
std::vector<Claim> project_targets(const std::vector<Table2Row>& table2);

/// The sanity line beside NoCompression, computed from that claim (its measurement and interval, no resampling of its
/// own): TC-SB without compression should not be much *faster* than plain Bullet either — more than 3 % faster
/// (interval's upper end < 1 - kNoCompressionMargin) points at an unfair, slow baseline. An at-least claim on the
/// same interval: fail (the flag) when all of it lies below 0.97, pass when all of it lies at or above, undecided
/// otherwise. Reported beside the claims, never gating the exit code.
Claim nocompression_sanity(const Claim& nocompression);

/// What `tcsb reproduce` aims to stay within, extra repetitions of undecided claims included (seconds): its default
/// budget for those repetitions is what is left of it, and the wall-time target judges the run against it.
inline constexpr double kReproductionWallTargetS = 150.0;

/// This project's target for the reproduction's wall time: within kReproductionWallTargetS (one measurement: judged
/// on its value).
Claim wall_time_target(double wall_s);

/// The cases a claim or target above is measured from, by its id; nullopt for an id that is not one of them (or
/// not measured from repetitions).
std::optional<ClaimScope> scope_of(std::string_view claim_id);

}  // namespace tcsb
