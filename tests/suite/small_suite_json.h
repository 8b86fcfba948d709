// A small valid suite as JSON, for tests that change one field of it and parse it: two nets (9x9 and 11x11), plain
// and TC-SB at 1.0 and 0.5, 20 steps after 5 warm-up steps, two repetitions.
#pragma once

#include <nlohmann/json.hpp>

namespace tcsb::testing {

inline nlohmann::json small_suite_json() {
  return nlohmann::json::parse(R"({
    "name": "axes", "nets": [{"name": "n9", "width": 9, "height": 9}, {"name": "n11", "width": 11, "height": 11}],
    "methods": ["plain", "tcsb"], "compression": [1.0, 0.5], "dt": 0.02, "steps": 20, "warmup_steps": 5,
    "repetitions": 2, "seed": 7, "solver": {"piterations": 2}})");
}

}  // namespace tcsb::testing
