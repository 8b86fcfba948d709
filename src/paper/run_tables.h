// Everything the renderers show of a finished run, computed once: per case its same-run ratios, the paper's tables
// and fits (of the whole run, or of each configuration of a suite with axes), and the fidelity tables. Every report
// (report/: native JSON, console, shard and merged results) receives this value and computes nothing, so two
// renderings of one run cannot disagree, and a run is summarised once however many renderings it has.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "paper/fidelity_tables.h"
#include "paper/paper_tables.h"
#include "paper/world_equal_error.h"
#include "run/run_result.h"

namespace tcsb {

/// One case's same-run ratios, paired by repetition (paired_ratio).
struct CaseRatios {
  std::optional<double> vs_plain;        ///< against the plain case of its net and configuration
  bool has_equal_plain = false;          ///< the run has the case's plain_equal partner (TC-SB cases only)
  std::optional<double> vs_equal_plain;  ///< against that partner
};

/// The paper's tables and fits of a run, or of one configuration's share of it.
struct TableSet {
  std::vector<std::size_t> cases;  ///< the run's case indices these tables cover, in run order
  std::vector<Table1Row> table1;
  std::vector<Table2Row> table2;
  std::vector<StepFit> step_fits;  ///< Figure 5, per (method, compression) group
  std::vector<OpFit> op_fits;      ///< Figure 4, per operation kind
};

/// A run's tables: per configuration when its suite has axes (a mean over configurations would mix settings; the
/// run-wide set is then left empty), else one set of the whole run.
struct RunTables {
  std::vector<CaseRatios> case_ratios;     ///< per case of the run, in run order
  TableSet whole;                          ///< every case; empty tables when the suite has axes
  std::vector<TableSet> configurations;    ///< one per configuration of a suite with axes; none without
  std::optional<FidelityTables> fidelity;  ///< with a fidelity pass
  /// With a world pass that ran its curves (fidelity.curves): its speed-up at equal error.
  std::optional<WorldEqualError> world_equal_error;
};

/// The tables of `result` as it stands.
RunTables run_tables(const RunResult& result);

}  // namespace tcsb
