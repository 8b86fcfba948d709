// The native JSON format (`--format json`): the native document (report/json_report.h) as text.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "report/report_format.h"

namespace tcsb {

/// The native JSON format: native_json() indented by 2, newline-terminated.
class NativeJsonFormat final : public ReportFormat {
 public:
  /// "json".
  std::string name() const override { return "json"; }
  /// The document as text (json_text), re-indented.
  std::string render_native(const nlohmann::ordered_json& native) const override;
};

}  // namespace tcsb
