#include "suite/suite_fields.h"

#include <charconv>

namespace tcsb::suite_fields {

std::string fmt_number(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string describe(const json& j) {
  std::string text;
  if (j.is_string())
    text = "string " + j.dump();
  else if (j.is_object())
    text = "an object";
  else if (j.is_array())
    text = "an array";
  else
    text = j.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

std::string key_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

}  // namespace tcsb::suite_fields
