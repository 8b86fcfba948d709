#include "report/claims_console.h"

#include <algorithm>

#include "report/text_table.h"

namespace tcsb {

namespace {

std::string decided_text(const Claim& c) {
  const std::optional<bool> d = decided(c);
  if (!d) return "-";
  return *d ? "yes" : "no";
}

}  // namespace

void print_claims(const char* title, const std::vector<Claim>& claims, std::ostream& out) {
  using Align = TextTable::Align;
  // The interval columns only when some claim has an interval (the reproduction's timing claims do).
  const bool intervals = std::any_of(claims.begin(), claims.end(), [](const Claim& c) { return c.interval; });
  std::vector<TextTable::Column> columns{
      {"id", Align::kLeft}, {"check", Align::kLeft}, {"expected"}, {"measured"}, {"verdict", Align::kLeft}};
  if (intervals) {
    columns.insert(columns.begin() + 4, {"95% interval"});
    columns.push_back({"beyond noise", Align::kLeft});
  }
  TextTable t(columns);
  for (const Claim& c : claims) {
    std::vector<std::string> row{c.id, comparison_name(c.comparison), general(c.expected, 4), general(c.measured, 4),
                                 c.pass ? "pass" : "FAIL"};
    if (intervals) {
      row.insert(row.begin() + 4,
                 c.interval ? general(c.interval->low, 4) + " - " + general(c.interval->high, 4) : std::string("-"));
      row.push_back(decided_text(c));
    }
    t.add_row(row);
  }
  out << title << "\n";
  t.print(out);
}

}  // namespace tcsb
