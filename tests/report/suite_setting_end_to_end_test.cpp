// One setting of the suite settings table end to end, feedback.contact_saliency: read from the suite file, refused
// out of its range with one line naming the file and the field, swept by an axis, and recorded in the result's suite
// block only when set. Its row in suite/suite_settings_table.cpp is all that makes it so.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "../suite/small_suite_json.h"
#include "report/json_report.h"
#include "suite/suite_axes.h"

namespace tcsb {
namespace {

using json = nlohmann::json;

Suite parse_contact_suite(const json& suite) { return parse_suite_text(suite.dump(), "contact.json"); }

TEST(SuiteSettingEndToEnd, ContactSaliencyIsRead) {
  json suite = testing::small_suite_json();
  suite["feedback"]["contact_saliency"] = 0.3;
  EXPECT_EQ(parse_contact_suite(suite).feedback.contact_saliency, 0.3);
  EXPECT_EQ(parse_contact_suite(testing::small_suite_json()).feedback.contact_saliency, 0.0);  // the default
}

TEST(SuiteSettingEndToEnd, ContactSaliencyOutOfRangeIsRefusedNamingFileAndField) {
  json suite = testing::small_suite_json();
  suite["feedback"]["contact_saliency"] = 1.5;
  try {
    parse_contact_suite(suite);
    ADD_FAILURE() << "a contact saliency of 1.5 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "contact.json: feedback.contact_saliency: must be a number in [0, 1], got 1.5");
  }
}

TEST(SuiteSettingEndToEnd, ContactSaliencyIsSweptByAnAxis) {
  json suite = testing::small_suite_json();
  suite["axes"] = {{"feedback.contact_saliency", {0, 0.5}}, {"solver.piterations", {2, 4}}};
  const Suite s = parse_contact_suite(suite);
  ASSERT_EQ(s.configurations.size(), 4u);
  EXPECT_EQ(s.configurations[3].label, "piterations=4,contact_saliency=0.5");  // a new axis comes last in labels
  EXPECT_EQ(configuration_suite(s, 3).feedback.contact_saliency, 0.5);
  EXPECT_EQ(configuration_suite(s, 2).feedback.contact_saliency, 0.0);
  suite["axes"] = {{"feedback.contact_saliency", {0.5, 2}}};
  try {
    parse_contact_suite(suite);
    ADD_FAILURE() << "an axis value of 2 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "contact.json: axes.feedback.contact_saliency[1]: must be a number in [0, 1], got 2");
  }
}

TEST(SuiteSettingEndToEnd, ContactSaliencyIsWrittenOnlyWhenSet) {
  EXPECT_FALSE(suite_json(parse_contact_suite(testing::small_suite_json()))["feedback"].contains("contact_saliency"));
  json suite = testing::small_suite_json();
  suite["feedback"]["contact_saliency"] = 0.3;
  EXPECT_EQ(suite_json(parse_contact_suite(suite))["feedback"]["contact_saliency"], 0.3);
}

}  // namespace
}  // namespace tcsb
