#include "report/report_format.h"

#include "report/json_report.h"

namespace tcsb {

std::string ReportFormat::render(const RunResult& result) const { return render_native(native_json(result)); }

}  // namespace tcsb
