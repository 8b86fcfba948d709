// Markdown tables from the generic JSON document (report/markdown_export.h): numbers as cells, lookups that never throw
// on a missing or mistyped value, cell text for any JSON value, and columns and tables built from them.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace tcsb {

/// A number with `digits` significant digits in plain decimal notation (no exponent unless |value| < 0.001);
/// "" when `value` is not a number (null, missing, a string).
std::string markdown_number(const nlohmann::ordered_json& value, int digits = 4);

}  // namespace tcsb

namespace tcsb::markdown {

using ojson = nlohmann::ordered_json;

/// The null every missing lookup returns (never inserted anywhere).
const ojson& null_json();

/// `object[key]`, or null when `object` is not an object or lacks the key: a hand-made or older file never throws.
const ojson& at(const ojson& object, const std::string& key);

/// The element of `array` whose `key1` and `key2` equal the given values, or null.
const ojson& find_row(const ojson& array, const std::string& key1, const ojson& value1, const std::string& key2,
                      const ojson& value2);

/// `value` times `factor` as a JSON number, or null when `value` is not a number.
ojson scaled(const ojson& value, double factor);

/// `part` as a percentage of `whole`, or null when either is missing or `whole` is 0.
ojson percent_of(const ojson& part, const ojson& whole);

/// Text safe inside a table cell: a `|` would end the cell, a newline the row.
std::string escaped(std::string_view text);

/// Any JSON value as cell text: numbers by markdown_number, booleans yes/no, null as an empty cell; an object as
/// "key: value, ...", an interval as "low – high".
std::string text_of(const ojson& value);

/// A compression as the tables print it: "-" for none (plain Bullet), else a percentage of the net's nodes.
std::string compression_text(const ojson& compression);

/// One column of a Markdown table: its header and how a row (a JSON object) becomes its cell.
struct Column {
  std::string header;
  std::function<std::string(const ojson& row)> cell;
};

/// A column showing `row[key]`.
Column field(std::string header, std::string key, int digits = 4);

/// A Markdown table of `rows` (a JSON array; anything else gives no rows).
std::string table(const std::vector<Column>& columns, const ojson& rows);

/// True when `array` has a row for which `cell` is not empty.
bool any_cell(const ojson& array, const std::function<std::string(const ojson&)>& cell);

/// True for a JSON array with at least one element.
bool non_empty_array(const ojson& value);

}  // namespace tcsb::markdown
