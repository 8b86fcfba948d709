#include "report/native_json_format.h"

#include "report/json_report.h"

namespace tcsb {

std::string NativeJsonFormat::render_native(const nlohmann::ordered_json& native) const { return json_text(native); }

}  // namespace tcsb
