#include "report/claims_console.h"

#include "report/text_table.h"

namespace tcsb {

void print_claims(const char* title, const std::vector<Claim>& claims, std::ostream& out) {
  using Align = TextTable::Align;
  TextTable t({{"id", Align::kLeft}, {"check", Align::kLeft}, {"expected"}, {"measured"}, {"verdict", Align::kLeft}});
  for (const Claim& c : claims)
    t.add_row({c.id, comparison_name(c.comparison), general(c.expected, 4), general(c.measured, 4),
               c.pass ? "pass" : "FAIL"});
  out << title << "\n";
  t.print(out);
}

}  // namespace tcsb
