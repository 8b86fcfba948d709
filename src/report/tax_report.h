// The tax of adaptivity judged on finished runs (`tcsb tax`, gate/adaptivity_tax.h), as a console table and as a
// JSON document.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gate/adaptivity_tax.h"

namespace tcsb {

/// One row per net: nodes, runs, paired ratios, the median ratio, its interval, the verdict and the note; then the
/// overall verdict on its own line ("tcsb tax: pass" etc.).
void print_tax(const std::vector<NetTax>& nets, const TaxTarget& target, std::ostream& out);

/// {"tool": "tcsb", "tax": {"bound", "compression", "min_net_nodes", "over_nets", "confidence", "runs": [files],
/// "nets": [{"net", "configuration", "net_nodes", "runs", "ratios", "run_medians", "ratio", "interval": {"low", "high"}
/// or null, "verdict", "note"}], "verdict"}}; no NaN (unmeasured values are null).
nlohmann::ordered_json tax_json(const std::vector<NetTax>& nets, const TaxTarget& target,
                                const std::vector<std::string>& files);

}  // namespace tcsb
