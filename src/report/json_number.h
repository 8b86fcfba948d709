// Numbers as every document tcsb writes holds them: a non-finite value (NaN: nothing was measured) is null, so no
// result file ever holds NaN or Infinity. A header of its own so that each section's writer (fidelity, operation
// work, the reproduction, the tax) needs nothing of the native report that assembles them.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

namespace tcsb {

/// A number as JSON, or null when it is NaN or infinite.
nlohmann::ordered_json json_number(double value);

/// An optional number as JSON: null when absent or non-finite.
nlohmann::ordered_json json_number(const std::optional<double>& value);

/// An optional integer (a step, a count) as JSON: null when absent.
nlohmann::ordered_json json_integer(const std::optional<int>& value);

}  // namespace tcsb
