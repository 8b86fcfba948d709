// TextTable: aligned plain-text columns for the console report (no colour, no box drawing, so it reads the same
// in a terminal, a CI log and a file).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace tcsb {

/// A table of strings printed with every column padded to its widest cell.
class TextTable {
 public:
  /// Column alignment: text to the left, numbers to the right (so digits line up).
  enum class Align { kLeft, kRight };
  struct Column {
    std::string header;
    Align align = Align::kRight;
  };

  /// A table with these columns.
  explicit TextTable(std::vector<Column> columns);
  /// Appends a row; missing cells are empty, extra cells are dropped; control characters are escaped
  /// (terminal_safe).
  void add_row(std::vector<std::string> cells);
  /// True when no row has been added.
  bool empty() const { return rows_.empty(); }
  /// Writes the header, a dashed rule and the rows, each line indented by `indent` spaces.
  void print(std::ostream& out, int indent = 2) const;

 private:
  std::vector<Column> columns_;
  std::vector<std::vector<std::string>> rows_;
};

/// `value` with `decimals` digits after the point; "-" when absent or non-finite.
std::string fixed(std::optional<double> value, int decimals);

/// `value` printed with a printf pattern taking one double (e.g. "%+.1f").
std::string formatted(const char* pattern, double value);

/// `value` with `digits` significant digits (%g style); "-" when absent or non-finite.
std::string general(std::optional<double> value, int digits);

}  // namespace tcsb
