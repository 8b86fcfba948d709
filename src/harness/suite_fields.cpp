#include "harness/suite_fields.h"

#include <charconv>
#include <set>
#include <vector>

namespace tcsb::suite_fields {

std::string fmt_number(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string describe(const json& j) {
  std::string text;
  if (j.is_string()) text = "string " + j.dump();
  else if (j.is_object()) text = "an object";
  else if (j.is_array()) text = "an array";
  else text = j.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

std::string key_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

json parse_json(const std::string& text, const Reader& r) {
  struct Frame {
    bool is_array = false;
    std::size_t index = 0;
    std::string key;
    std::set<std::string> seen;
  };
  std::vector<Frame> stack;
  auto path = [&stack] {
    std::string p;
    for (const Frame& f : stack) p = f.is_array ? index_path(p, f.index) : key_path(p, f.key);
    return p;
  };
  // A value just ended in the innermost container: in an array, the next element gets the next index.
  auto value_done = [&stack] {
    if (!stack.empty() && stack.back().is_array) ++stack.back().index;
  };
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: stack.push_back(Frame{}); break;
      case json::parse_event_t::array_start: stack.push_back(Frame{true, 0, {}, {}}); break;
      case json::parse_event_t::key: {
        Frame& f = stack.back();
        f.key = parsed.get<std::string>();
        if (!f.seen.insert(f.key).second) r.fail(path(), "duplicate key (each key may appear once)");
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack.pop_back();
        value_done();
        break;
      case json::parse_event_t::value: value_done(); break;
    }
    return true;
  };
  try {
    return json::parse(text, callback);
  } catch (const json::exception& e) {
    std::string message = e.what();
    if (const auto close = message.find("] "); message.rfind("[json.exception", 0) == 0 && close != std::string::npos) {
      message.erase(0, close + 2);
    }
    std::replace(message.begin(), message.end(), '\n', ' ');
    r.fail("", "malformed JSON: " + message);
  }
}


}  // namespace tcsb::suite_fields
