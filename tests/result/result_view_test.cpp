// Reading result files back: every field the readers use is checked, and a bad one is named with its file.
#include "result/result_view.h"

#include <gtest/gtest.h>

#include "../gate/result_documents.h"

namespace tcsb {
namespace {

using testing::ojson;
using testing::result_doc;

std::string error_of(const ojson& doc) {
  try {
    read_result(doc, "r.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ResultView, ReadsCasesAndRepetitions) {
  const ResultView r = read_result(result_doc(), "r.json");
  EXPECT_EQ(r.file, "r.json");
  EXPECT_EQ(r.schema_version, 2);
  EXPECT_EQ(r.steps, 20);
  EXPECT_EQ(r.repetitions, 9);
  ASSERT_EQ(r.cases.size(), 4u);
  EXPECT_EQ(r.cases[1].label, "n9/tcsb@0.5");
  EXPECT_EQ(r.cases[1].method, "tcsb");
  EXPECT_FALSE(r.cases[1].compression.has_value());
  ASSERT_EQ(r.cases[1].repetitions.size(), 9u);
  EXPECT_DOUBLE_EQ(*r.cases[1].repetitions[0].mean_step_ms, 0.5);
  EXPECT_EQ(r.cases[1].repetitions[3].final_state_hash, "h3");
  EXPECT_EQ(r.cases[1].repetitions[3].operations, 7);
}

TEST(ResultView, ASettingAddedSinceReadsAsItsDefault) {
  ojson doc = result_doc();
  doc["suite"].erase("interleave_across_nets");  // a result written before suites had the field
  EXPECT_EQ(read_result(doc, "r.json").suite["interleave_across_nets"], false);
  doc["suite"]["interleave_across_nets"] = true;
  EXPECT_EQ(read_result(doc, "r.json").suite["interleave_across_nets"], true);
}

TEST(ResultView, PairsRatiosWithThePlainCaseOfTheSameNet) {
  const ResultView r = read_result(result_doc(), "r.json");
  EXPECT_EQ(plain_case_of(r, 1), 0u);
  EXPECT_EQ(plain_case_of(r, 3), 2u);
  EXPECT_EQ(plain_case_of(r, 2), 2u);
  const std::vector<double> ratios = paired_step_ratios(r, 1, 0);
  ASSERT_EQ(ratios.size(), 9u);
  for (const double q : ratios) EXPECT_DOUBLE_EQ(q, 0.5);
}

TEST(ResultView, WithAxesRatiosPairWithinAConfiguration) {
  // The same nets in two configurations: cases 0 and 1 of one, 2 and 3 of another, all on one net.
  ojson doc = result_doc();
  for (std::size_t i = 0; i < 4; ++i) {
    doc["cases"][i]["net"] = "n9";
    doc["cases"][i]["configuration"] = {{"label", i < 2 ? "blend_steps=2" : "blend_steps=4"},
                                        {"axes", {{"tcsb.blend_steps", i < 2 ? 2 : 4}}}};
  }
  doc["cases"][2]["method"] = "tcsb";
  doc["cases"][3]["method"] = "plain";
  const ResultView r = read_result(doc, "r.json");
  EXPECT_EQ(r.cases[2].configuration, "blend_steps=4");
  EXPECT_EQ(plain_case_of(r, 1), 0u);
  EXPECT_EQ(plain_case_of(r, 2), 3u) << "the plain case of its own configuration, not the first on the net";
}

TEST(ResultView, DivergedRepetitionsAreLeftOutOfSamples) {
  ojson doc = result_doc();
  doc["cases"][0]["repetitions"][2]["status"] = "diverged";
  doc["cases"][0]["repetitions"][2]["mean_step_ms"] = nullptr;
  const ResultView r = read_result(doc, "r.json");
  EXPECT_EQ(ok_step_times(r.cases[0]).size(), 8u);
  EXPECT_EQ(paired_step_ratios(r, 1, 0).size(), 8u) << "repetition 2 has no plain partner";
}

TEST(ResultView, BadFieldsAreNamedWithTheFile) {
  // The messages are base/json_fields.h's, the same for suites, results and shards.
  ojson doc = result_doc();
  doc["cases"][1]["repetitions"][3]["final_state_hash"] = 5;
  EXPECT_EQ(error_of(doc), "r.json: cases[1].repetitions[3].final_state_hash: must be a string, got 5");

  doc = result_doc();
  doc["cases"][0].erase("status");
  EXPECT_EQ(error_of(doc), "r.json: cases[0].status: required key is missing");

  doc = result_doc();
  doc["cases"][0]["repetitions"][0]["operations"] = 1.5;
  EXPECT_NE(error_of(doc).find("cases[0].repetitions[0].operations: must be an integer"), std::string::npos);

  doc = result_doc();
  doc["cases"][0]["mean_nodes"] = "many";
  EXPECT_EQ(error_of(doc), "r.json: cases[0].mean_nodes: must be a finite number >= 0 or null, got string \"many\"");

  doc = result_doc();
  doc["tool"] = "gbench";
  EXPECT_EQ(error_of(doc), "r.json: tool: not a tcsb result (\"tool\" is not \"tcsb\")");
  EXPECT_NE(error_of(ojson::array()).find("not a tcsb result"), std::string::npos);
}

TEST(ResultView, AnIntegerWithoutAFractionalPartIsAnInteger) {
  // One rule for every input (base/json_fields.h): 7.0 is 7, as the result schema's check also has it.
  ojson doc = result_doc();
  doc["cases"][1]["repetitions"][3]["operations"] = 7.0;
  EXPECT_EQ(read_result(doc, "r.json").cases[1].repetitions[3].operations, 7);
}

TEST(ResultView, ImpossibleStepTimesAreBadInput) {
  // An ok repetition timed every step, and a step takes time: zero, negative or missing cannot come from a run.
  const struct {
    ojson value;
    const char* expected;
  } cases[] = {
      {0.0, "r.json: cases[1].repetitions[3].mean_step_ms: must be > 0 (a step takes time), got 0.0"},
      {-0.5, "r.json: cases[1].repetitions[3].mean_step_ms: must be > 0 (a step takes time), got -0.5"},
      {nullptr, "r.json: cases[1].repetitions[3].mean_step_ms: null, but the repetition's status is \"ok\""},
  };
  for (const auto& c : cases) {
    ojson doc = result_doc();
    doc["cases"][1]["repetitions"][3]["mean_step_ms"] = c.value;
    EXPECT_EQ(error_of(doc).rfind(c.expected, 0), 0u) << error_of(doc);
  }
  // A diverged repetition may have no time, but never a negative one.
  ojson doc = result_doc();
  doc["cases"][1]["repetitions"][3]["status"] = "diverged";
  doc["cases"][1]["repetitions"][3]["mean_step_ms"] = nullptr;
  EXPECT_EQ(error_of(doc), "");
  doc["cases"][1]["repetitions"][3]["mean_step_ms"] = -1.0;
  EXPECT_NE(error_of(doc).find("cases[1].repetitions[3].mean_step_ms: must be > 0"), std::string::npos);
}

TEST(ResultView, NegativeCountsAndSpreadsAreBadInput) {
  for (const char* field : {"mean_nodes", "mean_links", "mean_interpolations"}) {
    ojson doc = result_doc();
    doc["cases"][2]["repetitions"][0][field] = -1.0;
    EXPECT_EQ(error_of(doc), std::string("r.json: cases[2].repetitions[0].") + field +
                                 ": must be a finite number >= 0 or null, got -1.0");
    doc = result_doc();
    doc["cases"][2][field] = -3.0;
    EXPECT_EQ(error_of(doc),
              std::string("r.json: cases[2].") + field + ": must be a finite number >= 0 or null, got -3.0");
  }
  for (const char* field : {"median", "stddev", "cv"}) {
    ojson doc = result_doc();
    doc["cases"][0]["step_ms"][field] = -0.25;
    EXPECT_EQ(error_of(doc),
              std::string("r.json: cases[0].step_ms.") + field + ": must be a finite number >= 0 or null, got -0.25");
  }
  // Zero is a real count: a plain net interpolates nothing.
  ojson doc = result_doc();
  doc["cases"][0]["mean_interpolations"] = 0.0;
  doc["cases"][0]["repetitions"][0]["mean_interpolations"] = 0.0;
  EXPECT_EQ(error_of(doc), "");
}

TEST(ResultView, IntegralFloatsAreIntegers) {
  ojson doc = result_doc();
  doc["cases"][0]["repetitions"][0]["operations"] = 3.0;
  EXPECT_EQ(read_result(doc, "r.json").cases[0].repetitions[0].operations, 3);
}

}  // namespace
}  // namespace tcsb
