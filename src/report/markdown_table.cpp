#include "report/markdown_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/text_table.h"

namespace tcsb {

using ojson = nlohmann::ordered_json;

std::string markdown_number(const ojson& value, int digits) {
  if (value.is_number_integer() || value.is_number_unsigned()) return value.dump();
  if (!value.is_number()) return "";
  const double x = value.get<double>();
  if (!std::isfinite(x)) return "";
  if (x == 0) return "0";
  char buf[64];
  const double magnitude = std::floor(std::log10(std::abs(x)));
  if (magnitude < -3) {
    std::snprintf(buf, sizeof buf, "%.*e", std::max(0, digits - 1), x);
    return buf;
  }
  const int decimals = std::max(0, digits - 1 - static_cast<int>(magnitude));
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

}  // namespace tcsb

namespace tcsb::markdown {

namespace {

/// An object as one cell: "key: value, ...", except that an interval leads with "low – high" and puts any other
/// keys (a confidence level, say) after it in parentheses.
std::string object_text(const ojson& object) {
  const bool interval = object.contains("low") && object.contains("high");
  std::string others;
  for (const auto& [key, value] : object.items()) {
    if (interval && (key == "low" || key == "high")) continue;
    others += (others.empty() ? "" : ", ") + key + ": " + text_of(value);
  }
  if (!interval) return others;
  const std::string range = text_of(object["low"]) + " – " + text_of(object["high"]);
  return others.empty() ? range : range + " (" + others + ")";
}

}  // namespace

const ojson& null_json() {
  static const ojson kNull;
  return kNull;
}

const ojson& at(const ojson& object, const std::string& key) {
  if (!object.is_object()) return null_json();
  const auto it = object.find(key);
  return it == object.end() ? null_json() : *it;
}

const ojson& find_row(const ojson& array, const std::string& key1, const ojson& value1, const std::string& key2,
                      const ojson& value2) {
  if (!array.is_array()) return null_json();
  for (const ojson& row : array) {
    if (at(row, key1) == value1 && at(row, key2) == value2) return row;
  }
  return null_json();
}

ojson scaled(const ojson& value, double factor) {
  return value.is_number() ? ojson(value.get<double>() * factor) : ojson(nullptr);
}

ojson percent_of(const ojson& part, const ojson& whole) {
  if (!part.is_number() || !whole.is_number() || whole.get<double>() == 0) return nullptr;
  return ojson(100.0 * part.get<double>() / whole.get<double>());
}

std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') {
      out += "\\|";
    } else if (c == '\n' || c == '\r') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

std::string text_of(const ojson& value) {
  switch (value.type()) {
    case ojson::value_t::string: return escaped(value.get_ref<const std::string&>());
    case ojson::value_t::boolean: return value.get<bool>() ? "yes" : "no";
    case ojson::value_t::number_integer:
    case ojson::value_t::number_unsigned:
    case ojson::value_t::number_float: return markdown_number(value);
    case ojson::value_t::array: {
      std::string out;
      for (const ojson& v : value) out += (out.empty() ? "" : ", ") + text_of(v);
      return out;
    }
    case ojson::value_t::object: return escaped(object_text(value));
    default: return "";
  }
}

std::string compression_text(const ojson& compression) {
  if (!compression.is_number()) return "-";
  return general(100.0 * compression.get<double>(), 3) + "%";
}

Column field(std::string header, std::string key, int digits) {
  return {std::move(header), [key = std::move(key), digits](const ojson& row) {
            const ojson& v = at(row, key);
            return v.is_number_float() ? markdown_number(v, digits) : text_of(v);
          }};
}

std::string table(const std::vector<Column>& columns, const ojson& rows) {
  std::string out = "|";
  for (const Column& c : columns) out += " " + c.header + " |";
  out += "\n|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|";
  out += "\n";
  if (!rows.is_array()) return out;
  for (const ojson& row : rows) {
    out += "|";
    for (const Column& c : columns) {
      const std::string cell = c.cell(row);
      out += cell.empty() ? " |" : " " + cell + " |";
    }
    out += "\n";
  }
  return out;
}

bool any_cell(const ojson& array, const std::function<std::string(const ojson&)>& cell) {
  if (!array.is_array()) return false;
  return std::any_of(array.begin(), array.end(), [&](const ojson& row) { return !cell(row).empty(); });
}

bool non_empty_array(const ojson& value) { return value.is_array() && !value.empty(); }

}  // namespace tcsb::markdown
