// The report tests render a run as the CLI does: its tables computed once (paper/run_tables.h), then handed to the
// renderer.
#pragma once

#include <iosfwd>
#include <string>

#include <nlohmann/json.hpp>

#include "paper/run_tables.h"
#include "report/console_report.h"
#include "report/fidelity_console.h"
#include "report/json_report.h"
#include "report/report_format.h"

namespace tcsb::testing {

inline nlohmann::ordered_json native_json_of(const RunResult& r) { return native_json(r, run_tables(r)); }

inline void print_console_report_of(const RunResult& r, std::ostream& out) {
  print_console_report(r, run_tables(r), out);
}

inline void print_fidelity_report_of(const RunResult& r, std::ostream& out) {
  print_fidelity_report(r, run_tables(r), out);
}

inline std::string render_of(const ReportFormat& format, const RunResult& r) { return format.render(r, run_tables(r)); }

}  // namespace tcsb::testing
