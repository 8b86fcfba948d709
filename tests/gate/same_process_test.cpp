// Two files of one process are told apart from two processes by their measurements, not their names or dates.
#include "gate/same_process.h"

#include <gtest/gtest.h>

#include "result_documents.h"

namespace tcsb {
namespace {

using testing::ojson;
using testing::result_doc;

TEST(SameProcess, ACopyWithItsDateOrWallTimeEditedIsTheSameProcess) {
  const ojson run = result_doc();
  ojson copy = run;
  copy["context"]["date_utc"] = "2030-01-01T00:00:00Z";
  copy["wall_s"] = 123.0;
  const std::string why = shared_measurement(read_result(run, "a.json"), read_result(copy, "b.json"));
  EXPECT_NE(why.find("case n9/plain has the same 9 repetition time(s)"), std::string::npos) << why;
}

TEST(SameProcess, AShardBesideTheResultMergedFromItIsTheSameProcess) {
  const ojson merged = result_doc();
  ojson shard = merged;
  shard["cases"].erase(0);  // the shard of the second net holds only its cases, measured once
  shard["cases"].erase(0);
  EXPECT_NE(shared_measurement(read_result(merged, "all.json"), read_result(shard, "shard.json")), "");
}

TEST(SameProcess, AShardSplitByRepetitionBesideTheMergedResultIsTheSameProcess) {
  // Issue 60: the shard holds some of every case's repetitions, the merged result all of them; no whole case is
  // alike, and `tcsb tax merged.json shard-1.json` pooled shard 1's repetitions twice.
  const ojson merged = result_doc();
  ojson shard = merged;
  for (ojson& c : shard["cases"]) {
    ojson kept = ojson::array();
    for (const ojson& r : c["repetitions"])
      if (r["repetition"].get<int>() % 3 == 0) kept.push_back(r);
    c["repetitions"] = kept;
  }
  const std::string why = shared_measurement(read_result(merged, "all.json"), read_result(shard, "shard.json"));
  EXPECT_NE(why.find("has the same 3 repetition time(s)"), std::string::npos) << why;
  EXPECT_NE(shared_measurement(read_result(shard, "shard.json"), read_result(merged, "all.json")), "");
  // One repetition alike, of many the two could share, is chance; two are not.
  ojson other = merged;
  for (std::size_t c = 0; c < other["cases"].size(); ++c) testing::scale_case(other, c, 1.001);
  other["cases"][0]["repetitions"][4] = merged["cases"][0]["repetitions"][4];
  EXPECT_EQ(shared_measurement(read_result(merged, "a.json"), read_result(other, "b.json")), "");
  other["cases"][1]["repetitions"][2] = merged["cases"][1]["repetitions"][2];
  EXPECT_NE(shared_measurement(read_result(merged, "a.json"), read_result(other, "b.json")), "");
}

TEST(SameProcess, AnotherProcessOrDisjointCasesShareNothing) {
  const ojson run = result_doc();
  ojson again = run;
  for (std::size_t c = 0; c < again["cases"].size(); ++c) testing::scale_case(again, c, 1.001);
  EXPECT_EQ(shared_measurement(read_result(run, "a.json"), read_result(again, "b.json")), "");
  ojson first = run, second = run;
  first["cases"].erase(2);
  first["cases"].erase(2);
  second["cases"].erase(0);
  second["cases"].erase(0);
  EXPECT_EQ(shared_measurement(read_result(first, "a.json"), read_result(second, "b.json")), "");
}

TEST(SameProcess, UntimedCasesProveNothing) {
  ojson run = result_doc();
  for (ojson& c : run["cases"])
    for (ojson& r : c["repetitions"]) {
      r["status"] = "diverged";
      r["mean_step_ms"] = nullptr;
    }
  EXPECT_EQ(shared_measurement(read_result(run, "a.json"), read_result(run, "b.json")), "");
}

}  // namespace
}  // namespace tcsb
