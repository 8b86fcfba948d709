#include "report/format_registry.h"

#include "report/equal_error_markdown.h"
#include "report/gbench_export.h"
#include "report/github_action_export.h"
#include "report/markdown_export.h"
#include "report/native_json_format.h"

namespace tcsb {
namespace {

template <class Format>
std::unique_ptr<ReportFormat> create() {
  return std::make_unique<Format>();
}

struct Registration {
  std::string_view name;
  std::unique_ptr<ReportFormat> (*create)();
};

// The registry is an explicit table rather than static self-registration: formats live in a static library, and
// the linker drops object files nothing references, so a self-registering format would silently vanish.
// To add a format: include its header above and add one line here.
constexpr Registration kFormats[] = {
    {"json", &create<NativeJsonFormat>},
    {"gbench", &create<GbenchFormat>},
    {"github-action-smaller", &create<GithubActionSmallerFormat>},
    {"github-action-bigger", &create<GithubActionBiggerFormat>},
    {"markdown", &create<MarkdownFormat>},
    {"markdown-headline", &create<HeadlineRowFormat>},
    {"markdown-verdict", &create<HeadlineVerdictFormat>},
};

}  // namespace

std::unique_ptr<ReportFormat> make_format(std::string_view name) {
  for (const Registration& r : kFormats) {
    if (r.name == name) return r.create();
  }
  return nullptr;
}

std::vector<std::string> format_names() {
  std::vector<std::string> names;
  for (const Registration& r : kFormats) names.emplace_back(r.name);
  return names;
}

}  // namespace tcsb
