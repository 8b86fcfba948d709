// Saliency: the paper's BSWDF restricted to animation features (§4, eqs. 1–2), evaluated per simulated node.
//
//   BSWDF = Illumination o (GlobalMotion (x) LocalMotion)
//
//  * Local motion: a node moving differently from its neighbours pops out — |v_i - mean of its cut neighbours' v|,
//    normalised by the largest such value in the body, so the result lies in [0, 1] and uniform motion gives 0.
//  * Global motion: a fast object draws attention but limits focus (Yee et al. 2001), so it caps the saliency:
//    cap = 1 / (1 + |v_cm| / global_motion_scale); the (x) operator clamps local motion to that cap.
//  * Illumination (optional): Lambertian, o is a product with max(0, n . l), n the cloth normal at the node.
//  * Contact (optional, not in the paper): a node in contact with a rigid collider is at least contact_saliency
//    salient, after the cap and the light.
//  * View (optional, feedback.view): with a spectator (a ScreenProjection), local and global motion are measured on
//    the image — the relative velocity's projection, in degrees of visual angle per second — so motion far away or
//    along the line of sight counts little; a node in view is worth its block's apparent size x (view_static_share
//    + (1 - view_static_share) x its capped motion), and a node out of view gets 0 whatever else it has, as does a
//    node the body's own surface hides when the camera models occlusion (`seen`, surface_occlusion.h;
//    docs/design.md, "The spectator").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "../feedback/cut_snapshot.h"
#include "../feedback/feedback_settings.h"
#include "../view/screen_projection.h"

namespace tcsb {

/// Sums of the cut neighbours' velocities and their counts, per simulated node: one pass over the links (those
/// joining two committed nodes), in link order, so the sums are the same on every run.
struct NeighbourSums {
  std::vector<std::array<float, 3>> sum;
  std::vector<std::uint8_t> count;
};
void neighbour_sums(const CutSnapshot& snapshot, NeighbourSums& out);

/// Raw local motion |v_i - mean neighbour v| (m/s) for simulated nodes [begin, end); nodes that are not in the
/// committed cut, or have no neighbour, get 0. With a `view` (snapshot positions required) the relative velocity's
/// speed across the image instead, degrees per second, and 0 for a node out of view. Ranges are independent: any
/// split over threads gives the same numbers.
void local_motion(const CutSnapshot& snapshot, const NeighbourSums& sums, std::size_t begin, std::size_t end,
                  std::span<float> out, const ScreenProjection* view = nullptr);

/// Speed of the body's centre of mass, m/s (leaf masses from the tree; committed nodes only).
double global_motion(const CutSnapshot& snapshot);

/// Speed of the body's centre of mass across the image, degrees per second (requires snapshot positions); 0 when
/// it is behind the camera.
double projected_global_motion(const CutSnapshot& snapshot, const ScreenProjection& view);

/// Cap on saliency for a body moving at `speed`: 1 / (1 + speed / scale).
double global_motion_cap(double speed, double scale);

/// Lambertian factor max(0, n . l) at node i, n from the neighbours' positions (requires snapshot positions).
double lambert_factor(const CutSnapshot& snapshot, std::size_t i, const std::array<double, 3>& light);

/// The grid's spacing at rest, metres: the distance between its first two leaves (neighbours along a row); 0 for a
/// single leaf.
double grid_spacing(const LodTree& tree);

/// The side of tree node `id`'s block at rest, metres: its leaves across (the larger of its two extents) x `spacing`.
double block_side(const LodTree& tree, TreeId id, double spacing);

/// Turns raw local motion into saliency in place: divide by the largest value, clamp to the global cap, apply the
/// illumination factor when enabled, raise nodes in contact to the contact saliency (when the snapshot has contacts);
/// with a `view`, the cap from the projected global motion and 0 for every node out of view. With `seen` (per node,
/// 1 where the camera sees it; empty when the camera does not model occlusion) a node it does not see is out of view:
/// 0, and its motion does not enter the largest value. Deterministic for a given snapshot.
void finish_saliency(const CutSnapshot& snapshot, const FeedbackSettings& settings, std::span<float> motion,
                     const ScreenProjection* view = nullptr, std::span<const std::uint8_t> seen = {});

/// All of the above on one thread: saliency of every simulated node of the snapshot.
std::vector<float> compute_saliency(const CutSnapshot& snapshot, const FeedbackSettings& settings,
                                    const ScreenProjection* view = nullptr, std::span<const std::uint8_t> seen = {});

}  // namespace tcsb
