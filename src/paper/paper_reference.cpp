#include "paper/paper_reference.h"

#include <nlohmann/json.hpp>

#include "base/json_fields.h"
#include "base/json_file.h"

namespace tcsb {

double PaperReference::time_ratio(const std::string& compression) const {
  double plain = 0, tc = 0;
  for (const PaperTable2Row& r : table2) {
    if (r.method == "Bullet SoftBody") plain = r.total_ms;
    if (r.method == "TC-SB" && r.compression == compression) tc = r.total_ms;
  }
  return plain > 0 ? tc / plain : 0.0;
}

PaperReference load_paper_reference(const std::filesystem::path& path) {
  const JsonFields<nlohmann::json> f(path.string());
  const nlohmann::json root = read_json_file<nlohmann::json>(path, kSuiteJsonLimits);
  f.object(root, "");
  // The tables' figures are counts, times and shares: never negative.
  const NumberRange figure{0.0, false};
  PaperReference ref;
  if (root.contains("source")) ref.source = f.string(root, "", "source");
  if (root.contains("hardware")) ref.hardware = f.string(root, "", "hardware");
  const nlohmann::json& t1 = f.array(f.object(root, "", "table1"), "table1", "rows");
  for (std::size_t i = 0; i < t1.size(); ++i) {
    const std::string at = index_path("table1.rows", i);
    const nlohmann::json& r = f.object(t1[i], at);
    ref.table1.push_back({f.string(r, at, "operation"), f.number(r, at, "N", figure), f.number(r, at, "L", figure),
                          f.number(r, at, "node_ops_ms", figure), f.number(r, at, "node_ops_pct", figure),
                          f.number(r, at, "link_ops_ms", figure), f.number(r, at, "link_ops_pct", figure),
                          f.number(r, at, "complete_ms", figure)});
  }
  const nlohmann::json& t2 = f.array(f.object(root, "", "table2"), "table2", "rows");
  for (std::size_t i = 0; i < t2.size(); ++i) {
    const std::string at = index_path("table2.rows", i);
    const nlohmann::json& r = f.object(t2[i], at);
    ref.table2.push_back({f.string(r, at, "method"), f.string(r, at, "compression"), f.number(r, at, "N", figure),
                          f.number(r, at, "L", figure), f.number(r, at, "I", figure),
                          f.number(r, at, "total_ms", figure)});
  }
  return ref;
}

}  // namespace tcsb
