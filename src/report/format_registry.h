// The output formats by name (`--format NAME`): a registry apart from the interface (report/report_format.h), so the
// formats include the interface and only the registry includes the formats.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "report/report_format.h"

namespace tcsb {

/// The format called `name`, or nullptr if there is none. Formats are registered in format_registry.cpp's table.
std::unique_ptr<ReportFormat> make_format(std::string_view name);

/// Every registered format's name, in registration order (for --help and error messages).
std::vector<std::string> format_names();

}  // namespace tcsb
