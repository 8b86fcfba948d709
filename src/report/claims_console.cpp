#include "report/claims_console.h"

#include <algorithm>
#include <string>

#include "report/text_table.h"

namespace tcsb {

namespace {

/// One table for plain and tracked claims: `tracked` is null for plain claims, else parallel to `claims`.
void print_table(const char* title, const std::vector<Claim>& claims, const std::vector<TrackedClaim>* tracked,
                 std::ostream& out) {
  using Align = TextTable::Align;
  // The interval columns only when some claim has an interval (the reproduction's timing claims do).
  const bool intervals = std::any_of(claims.begin(), claims.end(), [](const Claim& c) { return c.interval; });
  const bool looks =
      tracked && std::any_of(tracked->begin(), tracked->end(), [](const TrackedClaim& t) { return t.look > 0; });
  std::vector<TextTable::Column> columns{{"id", Align::kLeft}, {"check", Align::kLeft}, {"expected"}, {"measured"}};
  if (intervals) columns.push_back({tracked ? "interval" : "95% interval"});
  columns.push_back({"verdict", Align::kLeft});
  if (looks) {
    columns.push_back({"look"});
    columns.push_back({"reps"});
  }
  TextTable t(columns);
  for (std::size_t i = 0; i < claims.size(); ++i) {
    const Claim& c = claims[i];
    std::vector<std::string> row{c.id, comparison_name(c.comparison), general(c.expected, 4), general(c.measured, 4)};
    if (c.comparison == Comparison::kWithin)
      row[2] = general(c.expected - c.tolerance, 4) + " - " + general(c.expected + c.tolerance, 4);
    if (intervals) row.push_back(c.interval ? general(c.interval->low, 4) + " - " + general(c.interval->high, 4) : "-");
    row.push_back(verdict_text(verdict(c)));
    if (looks) {
      const TrackedClaim& k = (*tracked)[i];
      row.push_back(k.look > 0 ? std::to_string(k.look) : "-");
      row.push_back(k.look > 0 ? std::to_string(k.repetitions) : "-");
    }
    t.add_row(row);
  }
  out << title << "\n";
  t.print(out);
}

}  // namespace

const char* verdict_text(Verdict v) {
  switch (v) {
    case Verdict::kPass: return "pass";
    case Verdict::kFail: return "FAIL";
    case Verdict::kUndecided: return "undecided";
  }
  return "?";
}

void print_claims(const char* title, const std::vector<Claim>& claims, std::ostream& out) {
  print_table(title, claims, nullptr, out);
}

void print_claims(const char* title, const std::vector<TrackedClaim>& claims, std::ostream& out) {
  std::vector<Claim> plain;
  for (const TrackedClaim& t : claims) plain.push_back(t.claim);
  print_table(title, plain, &claims, out);
}

}  // namespace tcsb
