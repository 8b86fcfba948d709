// RandomPolicy: seeded random refine/coarse choices steering a TC-SB body towards a node count. The ablation
// against saliency, and the driver that measures operations (Table 1) independently of the feedback stage.
#pragma once

#include <cstdint>
#include <random>

#include "../softbody/tc_softbody.h"

namespace tcsb {

/// Begins random operations on a TcSoftBody: coarse while the committed cut is above the target, refine while
/// below, and at the target a refine and a coarse together so operations keep flowing at a constant size.
class RandomPolicy {
 public:
  explicit RandomPolicy(std::uint64_t seed) : rng_(seed) {}

  /// Begins at most `max_ops` operations (O(max_ops) attempts, never a scan of the net); returns how many began.
  int apply(TcSoftBody& body, int target_nodes, int max_ops);

  /// Tries one refine of a random cut node (or the coarser neighbour that must be refined first).
  bool try_refine(TcSoftBody& body);
  /// Tries one coarse of the parent of a random cut node.
  bool try_coarse(TcSoftBody& body);

 private:
  TreeId random_cut_node(const TcSoftBody& body);
  std::mt19937_64 rng_;
};

}  // namespace tcsb
