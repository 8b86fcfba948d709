#include "report/equal_error_json.h"

#include "report/json_number.h"

namespace tcsb {

namespace {

using ojson = nlohmann::ordered_json;

ojson equal_error_point_json(const EqualErrorPoint& p) {
  ojson out = {{"method", p.method},
               {"compression", json_number(p.compression)},
               {"N", json_number(p.nodes)},
               {"time_ms", json_number(p.time_ms)},
               {"error", json_number(p.error)}};
  add_solver_divisor(p.method, p.solver_divisor, out);
  return out;
}

ojson rival_json(const EqualErrorRival& r) {
  return {{"status", equal_error_status_name(r.status)},
          {"time_ms", json_number(r.time_ms)},
          {"speedup", json_number(r.speedup)},
          {"interval",
           r.interval ? ojson{json_number(r.interval->low), json_number(r.interval->high)} : ojson(nullptr)}};
}

}  // namespace

void add_solver_divisor(const std::string& method, int divisor, ojson& out) {
  if (method == "full_resolution") out["solver_divisor"] = divisor;
}

ojson equal_error_json(const EqualErrorNet& n, const std::string& grid_rival) {
  const auto curve = [](const std::vector<EqualErrorPoint>& points) {
    ojson out = ojson::array();
    for (const EqualErrorPoint& p : points) out.push_back(equal_error_point_json(p));
    return out;
  };
  ojson rows = ojson::array();
  for (const EqualErrorRow& r : n.rows)
    rows.push_back({{"compression", json_number(r.compression)},
                    {"N", json_number(r.nodes)},
                    {"time_ms", json_number(r.time_ms)},
                    {"error", json_number(r.error)},
                    {grid_rival, rival_json(r.grid)},
                    {"full_resolution", rival_json(r.full)}});
  return {{"net", n.net},
          {"metric", n.metric},
          {"floor", json_number(n.floor)},
          {"missing", n.missing.empty() ? ojson(nullptr) : ojson(n.missing)},
          {"curves",
           {{"tcsb", curve(n.tcsb)},
            {grid_rival, curve(n.grid)},
            {"full_resolution", curve(n.full)},
            {"monotone",
             {{"tcsb", n.tcsb_monotone}, {grid_rival, n.grid_monotone}, {"full_resolution", n.full_monotone}}}}},
          {"rows", std::move(rows)}};
}

}  // namespace tcsb
