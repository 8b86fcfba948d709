#include "report/text_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "base/terminal_text.h"

namespace tcsb {

TextTable::TextTable(std::vector<Column> columns) : columns_(std::move(columns)) {}

void TextTable::add_row(std::vector<std::string> cells) {
  cells.resize(columns_.size());
  // Cells carry suite, net and case names from suite files: escaped here, once, for every table printed.
  for (std::string& cell : cells) cell = terminal_safe(cell);
  rows_.push_back(std::move(cells));
}

void TextTable::print(std::ostream& out, int indent) const {
  std::vector<std::size_t> width(columns_.size());
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    width[c] = columns_[c].header.size();
    for (const auto& row : rows_) width[c] = std::max(width[c], row[c].size());
  }
  const std::string margin(static_cast<std::size_t>(std::max(indent, 0)), ' ');
  const auto line = [&](const auto& cell_of) {
    std::string text = margin;
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      const std::string cell = cell_of(c);
      const std::string pad(width[c] - std::min(width[c], cell.size()), ' ');
      if (c > 0) text += "  ";
      text += columns_[c].align == Align::kLeft ? cell + pad : pad + cell;
    }
    // Trailing blanks of a left-aligned last column are noise in logs.
    text.erase(text.find_last_not_of(' ') + 1);
    out << text << '\n';
  };
  line([&](std::size_t c) { return columns_[c].header; });
  line([&](std::size_t c) { return std::string(width[c], '-'); });
  for (const auto& row : rows_) line([&](std::size_t c) { return row[c]; });
}

std::string fixed(std::optional<double> value, int decimals) {
  if (!value || !std::isfinite(*value)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, *value);
  return buf;
}

std::string general(std::optional<double> value, int digits) {
  if (!value || !std::isfinite(*value)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, *value);
  return buf;
}

std::string formatted(const char* pattern, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, pattern, value);
  return buf;
}

}  // namespace tcsb
