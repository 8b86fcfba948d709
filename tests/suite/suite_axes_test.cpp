// Suite axes: expansion into configurations, their labels and settings, the cases they make, and every kind of bad
// axis refused with one InputError naming the file and the field.
#include "suite/suite_axes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "small_suite_json.h"
#include "suite/case_plan.h"
#include "suite/suite_memory.h"

namespace tcsb {
namespace {

using json = nlohmann::json;

Suite with_axes(const json& axes) {
  json j = testing::small_suite_json();
  j["axes"] = axes;
  return parse_suite_text(j.dump(), "axes.json");
}

/// The message of the InputError parsing `axes` throws ("" when it throws none).
std::string rejection(const json& axes) {
  try {
    with_axes(axes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SuiteAxes, ExpandToTheCrossProductFirstAxisSlowestInSettingOrder) {
  // The file names blend_steps first; labels and configurations follow the settings' order (solver before tcsb).
  const Suite s = with_axes({{"tcsb.blend_steps", {2, 4, 8}}, {"solver.piterations", {2, 8}}});
  ASSERT_EQ(s.axes.size(), 2u);
  EXPECT_EQ(s.axes[0].path, "solver.piterations");
  EXPECT_EQ(s.axes[1].path, "tcsb.blend_steps");
  ASSERT_EQ(s.configurations.size(), 6u);
  const std::vector<std::string> labels = {"piterations=2,blend_steps=2", "piterations=2,blend_steps=4",
                                           "piterations=2,blend_steps=8", "piterations=8,blend_steps=2",
                                           "piterations=8,blend_steps=4", "piterations=8,blend_steps=8"};
  for (std::size_t c = 0; c < labels.size(); ++c) EXPECT_EQ(s.configurations[c].label, labels[c]);
  EXPECT_EQ(configuration_values(s, 4).dump(), R"({"solver.piterations":8,"tcsb.blend_steps":4})");
}

TEST(SuiteAxes, LabelsSpellValuesShortly) {
  const Suite s = with_axes({{"solver.damping", {0.5, 0.25}},
                             {"tcsb.placement", {"rigid"}},
                             {"feedback.illumination", {false}},
                             {"dt", {0.01}}});
  ASSERT_EQ(s.configurations.size(), 2u);
  EXPECT_EQ(s.configurations[0].label, "damping=0.5,placement=rigid,illumination=false,dt=0.01");
  EXPECT_EQ(s.configurations[1].label, "damping=0.25,placement=rigid,illumination=false,dt=0.01");
}

TEST(SuiteAxes, TheInterfacesAreASettingAndAnAxis) {
  json j = testing::small_suite_json();
  j["tcsb"] = {{"blend_steps", 4}, {"interfaces", "hanging"}};
  EXPECT_EQ(parse_suite_text(j.dump(), "axes.json").tcsb.interfaces, Interfaces::kHanging);
  const Suite s = with_axes({{"tcsb.interfaces", {"links", "hanging"}}});
  ASSERT_EQ(s.configurations.size(), 2u);
  EXPECT_EQ(s.configurations[1].label, "interfaces=hanging");
  EXPECT_EQ(configuration_suite(s, 0).tcsb.interfaces, Interfaces::kLinks);
  EXPECT_EQ(configuration_suite(s, 1).tcsb.interfaces, Interfaces::kHanging);
}

TEST(SuiteAxes, AConfigurationIsTheBaseSuiteWithItsValuesApplied) {
  const Suite s = with_axes({{"solver.piterations", {4, 8}}, {"seed", {11, 12}}, {"steps", {30, 40}}});
  const Suite c = configuration_suite(s, 4);  // the first axis slowest: piterations=8, seed=11, steps=30
  EXPECT_EQ(c.solver.piterations, 8);
  EXPECT_EQ(c.seed, 11u);
  EXPECT_EQ(c.steps, 30);
  EXPECT_TRUE(c.axes.empty());
  EXPECT_TRUE(c.configurations.empty());
  EXPECT_EQ(c.nets.size(), s.nets.size());
  EXPECT_EQ(c.repetitions, s.repetitions);
  // The base is untouched.
  EXPECT_EQ(s.solver.piterations, 2);
  EXPECT_EQ(s.seed, 7u);
  EXPECT_EQ(s.steps, 20);
  // The same suite with those settings and no axes is the configuration's suite.
  json j = testing::small_suite_json();
  j["solver"]["piterations"] = 8;
  j["seed"] = 11;
  j["steps"] = 30;
  const Suite alone = parse_suite_text(j.dump(), "axes.json");
  EXPECT_EQ(alone.solver.piterations, c.solver.piterations);
  EXPECT_EQ(alone.seed, c.seed);
  EXPECT_EQ(alone.steps, c.steps);
  EXPECT_EQ(configuration_suites(s).size(), 8u);
}

TEST(SuiteAxes, WithoutAxesTheSuiteIsItsOneConfiguration) {
  const Suite s = parse_suite_text(testing::small_suite_json().dump(), "axes.json");
  EXPECT_EQ(configuration_count(s), 1u);
  EXPECT_TRUE(s.configurations.empty());
  EXPECT_EQ(configuration_suite(s, 0).solver.piterations, 2);
  EXPECT_EQ(case_label(s, expand_cases(s)[2]), "n9/tcsb@0.5");
}

TEST(SuiteAxes, CasesRunPerConfigurationWithDistinctLabelsAndTheirAloneIndices) {
  const Suite s = with_axes({{"solver.piterations", {2, 8}}, {"tcsb.blend_steps", {2, 4}}});
  const std::vector<CaseKey> cases = expand_cases(s);
  ASSERT_EQ(cases.size(), 4u * 6u);  // 4 configurations x 2 nets x (plain, tcsb@1, tcsb@0.5)
  std::set<std::string> labels;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(cases[i].configuration, i / 6);
    EXPECT_EQ(cases[i].net, (i % 6) / 3);
    EXPECT_EQ(index_in_configuration(s, i), i % 6);
    labels.insert(case_label(s, cases[i]));
  }
  EXPECT_EQ(labels.size(), cases.size());
  EXPECT_EQ(case_label(s, cases[8]), "n9/tcsb@0.5[piterations=2,blend_steps=4]");
  EXPECT_EQ(case_label(s, cases[21]), "n11/plain[piterations=8,blend_steps=4]");
}

TEST(SuiteAxes, TheRecorderCountsEachConfigurationsSteps) {
  const Suite s = with_axes({{"steps", {10, 30}}});
  // 6 cases per configuration, 2 repetitions, (10 + 5) and (30 + 5) steps, 36 bytes a step.
  EXPECT_DOUBLE_EQ(recorder_peak_bytes(s), 6.0 * 2 * (15 + 35) * 36);
}

TEST(SuiteAxes, BadAxesAreRefusedNamingTheField) {
  EXPECT_EQ(rejection({{"solver.piterations", {2, "8"}}}),
            "axes.json: axes.solver.piterations[1]: must be an integer in [1, 1000], got string \"8\"");
  EXPECT_EQ(rejection({{"solver.piterations", {2, 0}}}),
            "axes.json: axes.solver.piterations[1]: must be an integer in [1, 1000], got 0");
  EXPECT_EQ(rejection({{"solver.damping", {0.5, 1.5}}}),
            "axes.json: axes.solver.damping[1]: must be a number in [0, 1), got 1.5");
  EXPECT_EQ(rejection({{"tcsb.placement", {"affine", "bent"}}}),
            "axes.json: axes.tcsb.placement[1]: must be one of \"affine\", \"rigid\", got string \"bent\"");
  EXPECT_EQ(rejection({{"tcsb.interfaces", {"links", "fans"}}}),
            "axes.json: axes.tcsb.interfaces[1]: must be one of \"links\", \"hanging\", got string \"fans\"");
  EXPECT_EQ(rejection({{"seed", {-1}}}), "axes.json: axes.seed[0]: must be a non-negative integer, got -1");
  EXPECT_EQ(rejection({{"solver.piterations", json::array()}}),
            "axes.json: axes.solver.piterations: must not be empty");
  EXPECT_EQ(rejection({{"solver.piterations", 2}}), "axes.json: axes.solver.piterations: must be an array, got 2");
  EXPECT_EQ(rejection({{"solver.piterations", {2, 8, 2}}}),
            "axes.json: axes.solver.piterations[2]: duplicate value 2 (also axes.solver.piterations[0])");
  EXPECT_EQ(rejection({{"dt", {0.01, 0.02, 0.01}}}), "axes.json: axes.dt[2]: duplicate value 0.01 (also axes.dt[0])");
  EXPECT_EQ(rejection(json::object()), "axes.json: axes: must name at least one setting");
  EXPECT_EQ(rejection({1, 2}), "axes.json: axes: must be an object of setting paths and value lists, got an array");
  const std::string unknown = rejection({{"solver.pitterations", {2}}});
  EXPECT_EQ(
      unknown.rfind("axes.json: axes.solver.pitterations: unknown setting (an axis is one of: solver.piterations, ", 0),
      0u)
      << unknown;
  const std::string fixed = rejection({{"repetitions", {2, 3}}});
  EXPECT_EQ(fixed.rfind("axes.json: axes.repetitions: cannot be an axis (", 0), 0u) << fixed;
  EXPECT_NE(rejection({{"feedback.threads", {1, 2}}}).find("axes.feedback.threads: cannot be an axis"),
            std::string::npos);
  EXPECT_NE(rejection({{"nets", {1}}}).find("axes.nets: cannot be an axis"), std::string::npos);
}

TEST(SuiteAxes, TooManyConfigurationsAreRefused) {
  json seeds = json::array(), steps = json::array();
  for (int i = 0; i < 40; ++i) seeds.push_back(i);
  for (int i = 1; i <= 26; ++i) steps.push_back(i);
  EXPECT_EQ(rejection({{"steps", steps}, {"seed", seeds}}),
            "axes.json: axes: 40 x 26 = 1040 configurations, more than the 1000 a suite may have");
  steps.erase(steps.size() - 1);  // 40 x 25 = 1000: the most allowed
  EXPECT_EQ(with_axes({{"steps", steps}, {"seed", seeds}}).configurations.size(), 1000u);
}

TEST(SuiteAxes, TheFidelityPassIsNotCombinedWithAxes) {
  json j = testing::small_suite_json();
  j["fidelity"] = {{"enabled", true}};
  j["axes"] = {{"solver.piterations", {2, 4}}};
  try {
    parse_suite_text(j.dump(), "axes.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "axes.json: fidelity.enabled: cannot be combined with axes");
  }
}

TEST(SuiteAxes, EverySettingThatCanBeAnAxisIsReadThroughTheAxisTable) {
  // Each axis-able path is a real setting whose reader accepts a valid value.
  const std::vector<std::string> paths = axis_setting_paths();
  EXPECT_EQ(paths.size(), 34u);
  for (const std::string& path : paths) {
    json value;
    if (path == "tcsb.placement")
      value = "rigid";
    else if (path == "tcsb.interfaces")
      value = "hanging";
    else if (path == "feedback.policy")
      value = "random";
    else if (path == "feedback.illumination" || path == "tcsb.restore_order" || path == "tcsb.exact_order" ||
             path == "tcsb.arrivals_collide" || path == "tcsb.rebuild_dbvt" ||
             path == "feedback.view")  // on, the view terms need a camera
      value = false;
    else if (path == "solver.damping" || path == "solver.stiffness" || path == "dt" ||
             path == "feedback.view_static_share" || path == "feedback.contact_saliency")
      value = 0.5;
    else
      value = 3;
    EXPECT_EQ(with_axes({{path, json::array({value})}}).configurations.size(), 1u) << path;
  }
}

}  // namespace
}  // namespace tcsb
