// Pin tension: where a boundary between cut levels costs most.
//
// A cloth hanging from pinned nodes carries its whole weight into them. Towards a point support the load is spread
// over an ever shorter ring, so the tension in the cloth grows roughly as 1/r with the distance r from the pin (a
// membrane's radial flow of force). Where a coarse block meets finer cloth, the fan of links between the two levels
// is not the fine cloth's material (feedback/interface_balance.h), and the cloth deviates in proportion to the load
// the fan carries: on the converged suite, level-1 blocks at the pinned corners with finer cloth around them erred
// about twice as much as the same cut without them (docs/methodology.md, "Boundaries near the pins"). This file turns
// the distance to the nearest pin into a weight on the interface charge. It is computed once per tree, in O(N).
#pragma once

#include <vector>

#include "../net/lod_tree.h"

namespace tcsb {

/// For every leaf of `tree` (grid node, in id order), the Euclidean distance in grid steps to the nearest pinned leaf:
/// exact, in O(N) (the two-pass distance transform of a sampled function, Felzenszwalb and Huttenlocher, Theory of
/// Computing 8, 2012). Infinity for every leaf when nothing is pinned.
std::vector<float> pin_distances(const LodTree& tree);

/// For every tree node, the weight 1 + tension x L / max(r, 1) of its level boundaries, where r is the distance
/// (pin_distances) of the block's nearest leaf to a pin and L the net's larger side in grid steps: scale-free, so the
/// same setting means the same on every net size. 1 everywhere when nothing is pinned or tension is 0.
std::vector<float> interface_weights(const LodTree& tree, double tension);

}  // namespace tcsb
