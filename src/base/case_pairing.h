// The pairing rule: a case of a run is compared with its base case in the same run — the plain case (Bullet's stock
// soft body) of the same net and configuration, or, for a TC-SB case with a node budget, the plain_equal case of
// that budget (a static body of as many nodes) — repetition by repetition: repetition r of the case with repetition r
// of its base, both ok, so a ratio is of two measurements made in the same round of the interleaved run (and, in a
// merged run, in the same process). One rule for the run itself (paper/paper_tables.h) and for a result file read
// back (result/result_view.h); each describes its cases to it through a PairingKey. In base/, the floor both stand on.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace tcsb {

/// Whether two compression targets are the same one (up to binary noise such as 100 * 0.3 = 30.000000000000004, or
/// a target read back from JSON).
inline bool same_compression(double a, double b) { return std::abs(a - b) < 1e-9; }

/// A case's part in the pairing: a base (plain, plain_equal), TC-SB, or neither (bullet_patch).
enum class PairingRole { kPlain, kPlainEqual, kTcsb, kOther };

/// What the pairing rule reads of a case. `Place` (equality-comparable, e.g. a std::tie of the net and the
/// configuration) is where the case ran: a ratio compares methods, never nets or settings.
template <class Place>
struct PairingKey {
  Place place;
  PairingRole role = PairingRole::kOther;
  std::optional<double> compression;  ///< the node budget of TC-SB and plain_equal cases
};

/// The plain case of the same place as cases[index], or nullopt. `key_of(case)` is the case's PairingKey.
template <class Case, class KeyOf>
std::optional<std::size_t> plain_partner(const std::vector<Case>& cases, std::size_t index, KeyOf key_of) {
  if (index >= cases.size()) return std::nullopt;
  const auto of = key_of(cases[index]);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto c = key_of(cases[i]);
    if (c.place == of.place && c.role == PairingRole::kPlain) return i;
  }
  return std::nullopt;
}

/// The plain_equal case of the same place and compression as the TC-SB case cases[index], or nullopt (cases[index]
/// is not TC-SB with a compression, or the run has no such case).
template <class Case, class KeyOf>
std::optional<std::size_t> equal_plain_partner(const std::vector<Case>& cases, std::size_t index, KeyOf key_of) {
  if (index >= cases.size()) return std::nullopt;
  const auto of = key_of(cases[index]);
  if (of.role != PairingRole::kTcsb || !of.compression) return std::nullopt;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto c = key_of(cases[i]);
    if (c.place == of.place && c.role == PairingRole::kPlainEqual && c.compression &&
        same_compression(*c.compression, *of.compression))
      return i;
  }
  return std::nullopt;
}

/// Calls pair(r, b) for each ok repetition r of a case, in its order, with b its base case's repetition of r's
/// number when that one is ok too. Repetitions pair by number, never by position: a case may lack one its base has.
/// `Repetition` has `repetition` (its number) and `status` ("ok" or "diverged").
template <class Repetition, class Pair>
void for_each_repetition_pair(const std::vector<Repetition>& repetitions, const std::vector<Repetition>& base,
                              Pair pair) {
  for (const Repetition& r : repetitions) {
    if (r.status != "ok") continue;
    const auto b =
        std::find_if(base.begin(), base.end(), [&](const Repetition& x) { return x.repetition == r.repetition; });
    if (b != base.end() && b->status == "ok") pair(r, *b);
  }
}

}  // namespace tcsb
