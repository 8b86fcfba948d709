#include "report/report_format.h"

#include "report/json_report.h"

namespace tcsb {

std::string ReportFormat::render(const RunResult& result, const RunTables& tables) const {
  return render_native(native_json(result, tables));
}

}  // namespace tcsb
