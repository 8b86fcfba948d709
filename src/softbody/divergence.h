// Divergence detection: a step that produced NaN or blew the body up must stop the run and be reported with its
// step, never averaged in.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <optional>
#include <string>

namespace tcsb {

/// O(1) check after each step: Bullet's own bounds (refreshed in predictMotion from the node tree's root) must be
/// finite and no larger than `max_extent` (a generous multiple of the net's size). Returns a reason when diverged.
std::optional<std::string> quick_divergence_check(const btSoftBody& body, double max_extent);

/// O(N + L) check, run outside the timed region every few steps and at the end: every position and velocity
/// finite, and no link longer than `max_link_length` metres. An absolute length, not a stretch ratio: a wide net
/// solved with few iterations legitimately stretches its corner links a hundredfold (Bullet's position solver moves
/// corrections a few links per step), while a link longer than the net itself only comes from an explosion.
std::optional<std::string> full_divergence_check(const btSoftBody& body, double max_link_length);

/// A body exploding is a result, not a crash: these bounds are generous enough never to trip on a sane cloth.
inline constexpr double kMaxExtentFactor = 10.0;     ///< bounds larger than 10x the net's size
inline constexpr double kMaxLinkLengthFactor = 2.0;  ///< a link longer than twice the net's size
inline constexpr int kFullCheckEvery = 50;           ///< steps between O(N + L) checks

/// The check a timed run makes after step `step` (0-based) of `total`: the quick check every step, the full check
/// every kFullCheckEvery steps and after the last, with the bounds above scaled by the net's extent. A divergence
/// found here may have begun up to kFullCheckEvery steps earlier: after last_full_check_before(step). The timed
/// runner finds the first diverged step by replaying (run/runner.cpp); untimed loops use divergence_now.
std::optional<std::string> divergence_after_step(const btSoftBody& body, double net_extent, int step, int total);

/// The last step before `step` after which divergence_after_step made its full check (-1: none). Every step up to
/// it passed both checks; the first diverged step lies after it.
constexpr int last_full_check_before(int step) { return step / kFullCheckEvery * kFullCheckEvery - 1; }

/// Both checks, whatever the step: what a loop that times nothing (or only what does not share the cache with the
/// check) runs after every step, so it reports the first diverged step.
std::optional<std::string> divergence_now(const btSoftBody& body, double net_extent);

}  // namespace tcsb
