#include "report/json_number.h"

#include <cmath>

namespace tcsb {

using ojson = nlohmann::ordered_json;

ojson json_number(double value) { return std::isfinite(value) ? ojson(value) : ojson(nullptr); }

ojson json_number(const std::optional<double>& value) { return value ? json_number(*value) : ojson(nullptr); }

ojson json_integer(const std::optional<int>& value) { return value ? ojson(*value) : ojson(nullptr); }

}  // namespace tcsb
