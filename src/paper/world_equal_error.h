// The world pass's speed-up at equal error (fidelity.curves in a scene of many bodies, world/world_runner.h): the
// fidelity pass's table (paper/equal_error_table.h) on the whole scene — TC-SB under one world budget across budgets,
// discrete LOD's curve across budgets, full resolution at fewer passes, the error the p95 in pixels over every body —
// and the world budget against per-body budgets at the same total node count. Computed from a WorldResult; every
// report renders it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "paper/equal_error_table.h"
#include "world/world_result.h"

namespace tcsb {

/// One budget of tcsb_world against tcsb_body's curve of error against total nodes.
struct WorldSameNodesRow {
  double budget = 0;
  double nodes = 0;         ///< tcsb_world's mean total nodes
  double world_p95_px = 0;  ///< tcsb_world's error
  /// tcsb_body's error at `nodes` (analysis/equal_error.h error_at_nodes: log-log between its two budgets whose mean
  /// nodes are around `nodes`); nullopt where its budgets do not reach so few or so many nodes.
  std::optional<double> body_p95_px;
  /// body_p95_px / world_p95_px: above 1, the world budget errs less than per-body budgets of the same total nodes.
  std::optional<double> ratio;
};

struct WorldEqualError {
  /// net "scene", metric "p95_px"; tcsb: tcsb_world's curve; grid: discrete LOD's; full: full resolution's at fewer
  /// passes. Both rivals' finest point is the reference at the noise floor.
  EqualErrorNet scene;
  std::vector<WorldSameNodesRow> same_nodes;  ///< per tcsb_world budget, ascending
};

/// The tables when the pass drew curves (it has a noise_floor row); nullopt otherwise. `seed` drives the bootstrap.
std::optional<WorldEqualError> world_equal_error(const WorldResult& result, std::uint64_t seed = 1);

}  // namespace tcsb
