// A tiny scene of many bodies as JSON, for the suite and world-pass tests: three 9x9 banners of 1 m in a row along x,
// each held along its top edge in a light wind, the camera flying past them on two keyframes, TC-SB sharing one world
// budget of half the scene's nodes, 40 steps after 20 warm-up steps (TC-SB comes down to its budget in them).
#pragma once

#include <nlohmann/json.hpp>

namespace tcsb::testing {

inline nlohmann::json world_suite_json() {
  return nlohmann::json::parse(R"({
    "name": "row", "nets": [{"name": "b9", "width": 9, "height": 9, "size": [1.0, 1.0], "elevation": 2.0,
                             "mass": {"total": 0.1}, "pinned": ["min_min", "max_min"]}],
    "methods": ["plain", "tcsb"], "compression": [1.0, 0.5], "dt": 0.016666666666666666, "steps": 40,
    "warmup_steps": 20, "repetitions": 1, "seed": 3, "solver": {"piterations": 4},
    "feedback": {"budget_scope": "world", "view": true, "max_ops_per_step": 16},
    "scene": {
      "wind": {"model": "V_TwoSidedLiftDrag", "velocity": [0.0, 0.0, 3.0], "lift": 0.2, "drag": 0.5},
      "camera": {"image": [320, 240], "path": [
        {"time": 0.0, "position": [-3.0, 1.5, -2.0], "target": [-3.0, 1.5, 0.0]},
        {"time": 0.75, "position": [3.0, 1.5, -2.0], "target": [3.0, 1.5, 0.0]}]},
      "bodies": [{"net": "b9", "position": [-3.0, 2.0, 0.0]}, {"net": "b9", "position": [0.0, 2.0, 0.0]},
                 {"net": "b9", "position": [3.0, 2.0, 0.0]}]
    }})");
}

}  // namespace tcsb::testing
