// What no run writes is refused before it is pooled or merged: cases on nets the suite lacks, node counts that are
// not the net's, repetitions numbered twice or missing.
#include "gate/run_consistency.h"

#include <gtest/gtest.h>

#include "result_documents.h"

namespace tcsb {
namespace {

using testing::ojson;

/// result_doc() with the suite block's nets and each case's net_nodes, as a run writes them.
ojson possible_run() {
  ojson doc = testing::result_doc(9);
  doc["suite"]["nets"] = ojson::array({{{"name", "n9"}, {"width", 9}, {"height", 9}, {"nodes", 81}},
                                       {{"name", "n17"}, {"width", 17}, {"height", 17}, {"nodes", 289}}});
  for (ojson& c : doc["cases"]) c["net_nodes"] = c["net"] == "n9" ? 81 : 289;
  return doc;
}

std::string problem(const ojson& doc) {
  try {
    check_run_is_possible(read_result(doc, "run.json"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RunConsistency, ARunAsWrittenIsPossible) { EXPECT_EQ(problem(possible_run()), ""); }

TEST(RunConsistency, NetNodesMustBeTheNetsWidthTimesHeight) {
  ojson doc = possible_run();
  doc["cases"][1]["net_nodes"] = 70000;
  EXPECT_NE(problem(doc).find("run.json: cases[1].net_nodes: 70000, but net n9 has 81 nodes"), std::string::npos)
      << problem(doc);
  doc = possible_run();
  doc["cases"][2]["net"] = "n1025";
  EXPECT_NE(problem(doc).find("cases[2].net: \"n1025\" is not a net of the suite"), std::string::npos);
}

TEST(RunConsistency, RepetitionsAreNumberedOnceEachAndNoneIsMissing) {
  ojson doc = possible_run();
  for (ojson& r : doc["cases"][0]["repetitions"]) r["repetition"] = 0;
  EXPECT_NE(problem(doc).find("cases[0].repetitions[1].repetition: repetition 0 appears twice"), std::string::npos)
      << problem(doc);
  doc = possible_run();
  doc["cases"][3]["repetitions"].erase(4);
  EXPECT_NE(problem(doc).find("cases[3].repetitions[7].repetition: 8, but the case has 8"), std::string::npos)
      << problem(doc);
  doc = possible_run();
  doc["cases"][3]["repetitions"].erase(8);
  EXPECT_NE(problem(doc).find("cases[3].repetitions: 8 repetitions, but the suite ran 9"), std::string::npos)
      << problem(doc);
}

}  // namespace
}  // namespace tcsb
