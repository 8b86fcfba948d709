// SurfaceMorph: TC-SB's reconstructed surface with every jump a step boundary makes spread over the next K + 1
// boundaries (or as many as a suite's fidelity.geomorph_boundaries says) — a geomorph (Hoppe, "Progressive Meshes",
// SIGGRAPH 1996, §4.2), as the paper's link blending spreads the physical change.
//
// At a boundary no simulated time passes, yet the committed cut's reconstruction (fidelity/reconstruction.h) can
// change: a coarsen or refine replaces a block's nodes, and every block whose neighbourhood changed (its links
// appearing, fading out, ending) takes another affine fit. The morph records the whole change, per leaf,
// D = before - after — the reconstruction at the same positions before the boundary's operations and after them —
// and shows after + (1 - a/(K+1)) D, a the boundaries since D was recorded (1 at its own, then 2, … until K+1, when
// it is spent). So the surface moves by at most D/(K+1) per boundary for each recent jump, while following the new
// nodes' motion. The jump is frozen when recorded, not recomputed from the leaving nodes, which are still simulated
// and drift from the cloth while their links fade (measured: mixing them in step by step popped 1.2-2.0 % of the
// net's extent at the worst step, docs/methodology.md, "Tried and left out").
//
// An earlier morph covered only each operation's own block, from its start: a block next to an operation, and an
// operation's block when it ended (its tethers leaving its fit), still jumped at once, and those were the worst pops
// of the converged suite (docs/methodology.md, "Popping: the jumps the geomorph did not cover").
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "softbody/tc_softbody.h"

namespace tcsb {

/// The geomorphed surface of one TC-SB body. Stateful; the calls must follow the body's steps:
///   reconstruct() once the body is built, and after every Bullet step;
///   boundary() at every step boundary at which the cut may have changed or a jump is still being spread
///   (morphing()), after the boundary's operations and before the next Bullet step.
class SurfaceMorph {
 public:
  /// `boundaries`: over how many boundaries a jump is spread (FidelitySettings::geomorph_boundaries); nullopt: the
  /// body's blend_steps + 1, the blend's own length.
  explicit SurfaceMorph(std::optional<int> boundaries = std::nullopt) : boundaries_(boundaries) {}
  /// Records the jump the boundary's operations made: the reconstruction now against the last reconstruct()'s (the
  /// same positions, the cut before the operations). Ages the jumps recorded before. O(N + cut size x degree).
  void boundary(const TcSoftBody& body);
  /// Every leaf of the body: reconstruct_leaves() of the committed cut plus the unspent part of each recorded jump.
  /// `leaves` is resized to the net's node count. O(N + cut size x degree).
  void reconstruct(const TcSoftBody& body, std::vector<Eigen::Vector3d>& leaves);
  /// Whether a recorded jump is still being spread (the surface moves at the next boundary even without operations).
  bool morphing() const { return !jumps_.empty(); }

 private:
  /// One boundary's jump over the leaves it moved.
  struct Jump {
    int age = 1;  ///< boundaries since it was recorded, its own included
    std::vector<std::int32_t> leaf;
    std::vector<Eigen::Vector3d> offset;  ///< D = before - after, per leaf
  };
  int spread(const TcSoftBody& body) const { return boundaries_ ? *boundaries_ : body.settings().blend_steps + 1; }

  std::optional<int> boundaries_;
  std::vector<Jump> jumps_;
  std::vector<Eigen::Vector3d> raw_;  // the committed cut's reconstruction at the last call
  bool fresh_ = false;                // raw_ was computed by boundary() and nothing moved since
};

}  // namespace tcsb
