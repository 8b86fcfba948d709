// PaperReference: the paper's own Tables 1 and 2, read from results/paper.json (verbatim copies, with their
// source), so a reproduction prints them beside what we measured and derives its claims' thresholds from them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tcsb {

/// One row of the paper's Table 1.
struct PaperTable1Row {
  std::string operation;
  double N = 0, L = 0, node_ops_ms = 0, node_ops_pct = 0, link_ops_ms = 0, link_ops_pct = 0, complete_ms = 0;
};

/// One row of the paper's Table 2.
struct PaperTable2Row {
  std::string method;       ///< "Bullet SoftBody" or "TC-SB"
  std::string compression;  ///< "-", "NoCompression", "75%", "30%"
  double N = 0, L = 0, I = 0, total_ms = 0;
};

/// The paper's tables.
struct PaperReference {
  std::string source, hardware;
  std::vector<PaperTable1Row> table1;
  std::vector<PaperTable2Row> table2;
  /// The paper's TC-SB time over its Bullet SoftBody time for a compression label ("30%"), or 0 if absent.
  double time_ratio(const std::string& compression) const;
};

/// Reads results/paper.json with the typed reader of every input (base/json_fields.h). Throws InputError "FILE:
/// FIELD: problem" on a bad file.
PaperReference load_paper_reference(const std::filesystem::path& path);

}  // namespace tcsb
