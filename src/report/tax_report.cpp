#include "report/tax_report.h"

#include "report/claims_console.h"
#include "report/json_number.h"
#include "report/text_table.h"

namespace tcsb {

void print_tax(const std::vector<NetTax>& nets, const TaxTarget& target, std::ostream& out) {
  using Align = TextTable::Align;
  const bool axes = std::any_of(nets.begin(), nets.end(), [](const NetTax& n) { return !n.configuration.empty(); });
  std::vector<TextTable::Column> columns{{"net", Align::kLeft}};
  if (axes) columns.push_back({"configuration", Align::kLeft});
  // Over the nets the row stands for several: its node count is the smallest net's.
  for (const char* header :
       {target.over_nets ? "smallest net" : "nodes", "runs", "processes", "ratios", "ratio", "interval"})
    columns.push_back({header});
  columns.push_back({"verdict", Align::kLeft});
  columns.push_back({"note", Align::kLeft});
  TextTable t(columns);
  for (const NetTax& n : nets) {
    std::vector<std::string> row{n.net};
    if (axes) row.push_back(n.configuration);
    const std::optional<Interval>& i = n.claim.interval;
    for (std::string cell :
         {std::to_string(n.net_nodes), std::to_string(n.runs), std::to_string(n.processes), std::to_string(n.ratios),
          fixed(n.claim.measured, 3), i ? fixed(i->low, 3) + " - " + fixed(i->high, 3) : "-"})
      row.push_back(std::move(cell));
    row.push_back(verdict_text(verdict(n.claim)));
    row.push_back(n.note);
    t.add_row(row);
  }
  out << "TC-SB at " << general(target.compression * 100.0, 4) << "% against plain_equal, "
      << (target.over_nets ? "over the nets" : "per net");
  if (target.min_net_nodes > 1) out << " of " << target.min_net_nodes << " nodes and more";
  out << " (bound " << general(target.bound, 4) << "; " << general(target.confidence * 100.0, 4)
      << "% intervals, runs resampled, then the processes of a merged run, then their repetitions)\n";
  t.print(out);
  out << "tcsb tax: " << verdict_name(tax_verdict(nets)) << "\n";
}

nlohmann::ordered_json tax_json(const std::vector<NetTax>& nets, const TaxTarget& target,
                                const std::vector<std::string>& files) {
  using ojson = nlohmann::ordered_json;
  ojson rows = ojson::array();
  for (const NetTax& n : nets) {
    ojson medians = ojson::array();
    for (const double m : n.run_medians) medians.push_back(json_number(m));
    const std::optional<Interval>& i = n.claim.interval;
    rows.push_back({{"net", n.net},
                    {"configuration", n.configuration},
                    {"net_nodes", n.net_nodes},
                    {"runs", n.runs},
                    {"processes", n.processes},
                    {"ratios", n.ratios},
                    {"run_medians", std::move(medians)},
                    {"ratio", json_number(n.claim.measured)},
                    {"interval", i ? ojson{{"low", json_number(i->low)}, {"high", json_number(i->high)}} : ojson()},
                    {"verdict", verdict_name(verdict(n.claim))},
                    {"note", n.note}});
  }
  return {{"tool", "tcsb"},
          {"tax",
           {{"bound", json_number(target.bound)},
            {"compression", json_number(target.compression)},
            {"min_net_nodes", target.min_net_nodes},
            {"over_nets", target.over_nets},
            {"confidence", json_number(target.confidence)},
            {"runs", files},
            {"nets", std::move(rows)},
            {"verdict", verdict_name(tax_verdict(nets))}}}};
}

}  // namespace tcsb
