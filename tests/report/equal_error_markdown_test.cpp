// The speed-up at equal error as Markdown: the headline row of a run's largest net, the verdict on 2x (three
// verdicts on the interval), a scene of many bodies read against discrete LOD, and the line a net without curves gets.
#include "report/equal_error_markdown.h"

#include <gtest/gtest.h>

#include <memory>

#include "report/format_registry.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

ojson interpolated_rival(double speedup, double low, double high) {
  return {{"status", "interpolated"}, {"time_ms", speedup}, {"speedup", speedup}, {"interval", {low, high}}};
}

/// A run with two nets: the small one with a large speed-up, the large one (the headline's) with `grid` at 30 %.
ojson headline_run(const ojson& grid) {
  const ojson row30 = {{"compression", 0.3},   {"N", 300},
                       {"time_ms", 1.5},       {"error", 4.25},
                       {"uniform_grid", grid}, {"full_resolution", interpolated_rival(3, 2.5, 3.5)}};
  const ojson row75 = {{"compression", 0.75},
                       {"N", 750},
                       {"time_ms", 3.0},
                       {"error", 1.0},
                       {"uniform_grid",
                        {{"status", "not_reached"}, {"time_ms", nullptr}, {"speedup", nullptr}, {"interval", nullptr}}},
                       {"full_resolution", interpolated_rival(1, 0.9, 1.1)}};
  const ojson small = {{"net", "s"},
                       {"metric", "rms_pct"},
                       {"missing", nullptr},
                       {"rows", {{{"compression", 0.3}, {"uniform_grid", interpolated_rival(9, 8, 10)}}}}};
  const ojson large = {{"net", "l"}, {"metric", "p95_px"}, {"missing", nullptr}, {"rows", {row30, row75}}};
  return {{"suite",
           {{"name", "scene"},
            {"nets", {{{"name", "s"}, {"nodes", 100}}, {{"name", "l"}, {"nodes", 1000}}}},
            {"feedback", {{"view", true}}},
            {"scene", {{"colliders", {{{"shape", "sphere"}}}}}},
            {"material", {{"model", "compliant"}}}}},
          {"fidelity", {{"equal_error", {{"nets", {small, large}}}}}}};
}

std::string render_as(const char* format, const ojson& doc) { return make_format(format)->render_native(doc); }

TEST(HeadlineExport, ARowOfTheLargestNetAtThirtyPercent) {
  const std::string row = render_as("markdown-headline", headline_run(interpolated_rival(1.25, 1.1, 1.4)));
  EXPECT_EQ(
      row,
      "| scene | compliant | viewer, contact | l, p95 px | 1.50 ms, 4.25 | 1.25× (1.10–1.40) | 3.00× (2.50–3.50) | "
      "1.25× (1.10–1.40) at 30% |\n");
}

TEST(HeadlineExport, TheVerdictOnTwoTimesIsThreeValued) {
  EXPECT_NE(render_as("markdown-verdict", headline_run(interpolated_rival(2.5, 2.1, 2.9))).find(": reaches 2.0×."),
            std::string::npos);
  const std::string short_of = render_as("markdown-verdict", headline_run(interpolated_rival(1.25, 1.1, 1.4)));
  EXPECT_NE(short_of.find("short of 2.0× by a factor of 1.60"), std::string::npos) << short_of;
  EXPECT_NE(render_as("markdown-verdict", headline_run(interpolated_rival(2.5, 1.5, 3))).find("undecided"),
            std::string::npos);
}

TEST(HeadlineExport, ANetWithoutCurvesSaysWhatIsMissing) {
  ojson doc = headline_run(interpolated_rival(1, 1, 1));
  doc["fidelity"]["equal_error"]["nets"][1]["missing"] = "no uniform grid ran to the end (fidelity.curves.budgets)";
  EXPECT_NE(render_as("markdown-headline", doc).find("no speed-up: no uniform grid ran"), std::string::npos);
  EXPECT_NE(render_as("markdown-verdict", doc).find("no speed-up could be computed"), std::string::npos);
  EXPECT_NE(render_as("markdown-headline", ojson{{"suite", {{"name", "x"}}}}).find("no curves"), std::string::npos);
}

TEST(HeadlineExport, AWorldPassIsReadAgainstDiscreteLod) {
  // A scene of many bodies has no per-net curves: its row is the world pass's whole scene against discrete LOD.
  ojson doc = headline_run(interpolated_rival(9, 8, 10));
  ojson scene = doc["fidelity"]["equal_error"]["nets"][1];
  scene["net"] = "scene";
  for (ojson& row : scene["rows"]) {
    row["discrete_lod"] = row["uniform_grid"];
    row.erase("uniform_grid");
  }
  scene["rows"][0]["discrete_lod"] = interpolated_rival(1.5, 1.25, 1.75);
  doc.erase("fidelity");
  doc["world"] = {{"equal_error", {{"scene", scene}}}};
  EXPECT_EQ(
      render_as("markdown-headline", doc),
      "| scene | compliant | viewer, contact | scene, p95 px, vs discrete LOD | 1.50 ms, 4.25 | 1.50× (1.25–1.75) | "
      "3.00× (2.50–3.50) | 1.50× (1.25–1.75) at 30% |\n");
  const std::string verdict = render_as("markdown-verdict", doc);
  EXPECT_NE(verdict.find("against discrete LOD is 1.50×"), std::string::npos) << verdict;
  doc["world"]["equal_error"]["scene"]["rows"][0]["discrete_lod"]["status"] = "at_cheapest";
  EXPECT_NE(render_as("markdown-verdict", doc).find("discrete LOD's curve"), std::string::npos);
}

TEST(HeadlineExport, TheRunsRenderHasTheSectionOnlyWithCurves) {
  EXPECT_EQ(equal_error_section(ojson{{"fidelity", ojson::object()}}), "");
  ojson doc = headline_run(interpolated_rival(1.25, 1.1, 1.4));
  doc["fidelity"]["equal_error"]["definition"] = "d";
  const std::string section = equal_error_section(doc);
  EXPECT_NE(section.find("### Speed-up at equal error"), std::string::npos);
  EXPECT_NE(section.find("not reached"), std::string::npos);
}

}  // namespace
}  // namespace tcsb
