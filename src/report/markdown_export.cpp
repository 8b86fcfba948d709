#include "report/markdown_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string_view>
#include <vector>

#include "report/equal_error_markdown.h"
#include "report/markdown_table.h"
#include "report/text_table.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;
using namespace markdown;

/// The first 7 hex digits, and "-dirty" when the build had uncommitted changes (the run is then not that commit's).
std::string short_commit(const ojson& commit) {
  if (!commit.is_string()) return "";
  const std::string text = commit.get<std::string>();
  return text.substr(0, 7) + (text.size() > 7 && text.ends_with("-dirty") ? "-dirty" : "");
}

/// "2026-11-22T09:27:13Z" as "2026-11-22 09:27:13 UTC"; any other text as it is.
std::string date_text(const ojson& date) {
  if (!date.is_string()) return "";
  std::string d = date.get<std::string>();
  if (d.size() == 20 && d[10] == 'T' && d.back() == 'Z') return d.substr(0, 10) + " " + d.substr(11, 8) + " UTC";
  return d;
}

std::string suite_name(const ojson& doc) {
  const ojson& name = at(at(doc, "suite"), "name");
  return name.is_string() ? name.get<std::string>() : "unnamed";
}

// ---- sections ----------------------------------------------------------------------------------------------------

std::string heading(const ojson& doc) {
  const ojson& context = at(doc, "context");
  std::string h = at(doc, "reproduction").is_object() ? "## Reproduction: suite `" : "## Run: suite `";
  h += suite_name(doc) + "`";
  if (const std::string date = date_text(at(context, "date_utc")); !date.empty()) h += ", " + date.substr(0, 10);
  if (const std::string commit = short_commit(at(context, "git_commit")); !commit.empty()) h += ", " + commit;
  return h + "\n";
}

std::string wall_text(const ojson& doc) {
  const ojson& reproduction = at(doc, "reproduction");
  const ojson& wall = at(reproduction, "wall_s").is_number() ? at(reproduction, "wall_s") : at(doc, "wall_s");
  if (!wall.is_number()) return "";
  std::string out = markdown_number(wall, 3) + " s wall";
  std::vector<std::string> parts;
  if (const ojson& f = at(at(doc, "fidelity"), "wall_s"); f.is_number())
    parts.push_back("fidelity pass " + markdown_number(f, 3) + " s");
  if (const ojson& b = at(reproduction, "bootstrap_s"); b.is_number())
    parts.push_back("claims' intervals " + markdown_number(b, 3) + " s");
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i == 0 ? " (" : ", ") + parts[i];
  return parts.empty() ? out : out + ")";
}

std::string suite_text(const ojson& doc) {
  const ojson& suite = at(doc, "suite");
  std::string out = "suite `" + suite_name(doc) + "`";
  std::vector<std::string> parts;
  if (const ojson& nets = at(suite, "nets"); nets.is_array()) parts.push_back(std::to_string(nets.size()) + " nets");
  if (const ojson& r = at(suite, "repetitions"); r.is_number_integer()) {
    std::string reps = text_of(r) + " repetitions";
    if (const ojson& s = at(suite, "steps"); s.is_number_integer()) reps += " of " + text_of(s) + " steps";
    parts.push_back(reps);
  }
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i == 0 ? " (" : ", ") + parts[i];
  return parts.empty() ? out : out + ")";
}

std::string command_text(const ojson& command) {
  if (command.is_string()) return command.get<std::string>();
  if (!command.is_array()) return "";
  std::string out;
  for (const ojson& word : command) {
    if (word.is_string()) out += (out.empty() ? "" : " ") + word.get<std::string>();
  }
  return out;
}

std::string build_text(const ojson& context) {
  std::string out = text_of(at(context, "compiler"));
  if (const std::string flags = text_of(at(context, "cxx_flags")); !flags.empty()) out += " `" + flags + "`";
  if (const std::string bullet = text_of(at(context, "bullet_version")); !bullet.empty()) {
    out += (out.empty() ? "Bullet " : ", Bullet ") + bullet;
    if (const std::string precision = text_of(at(context, "bullet_precision")); !precision.empty())
      out += " " + precision + " precision";
  }
  return out;
}

std::string source_line(const ojson& doc) {
  const ojson& context = at(doc, "context");
  std::vector<std::string> parts;
  const std::string command = command_text(at(context, "command"));
  parts.push_back(command.empty() ? suite_text(doc) : "`" + command + "`");
  parts.push_back(date_text(at(context, "date_utc")));
  if (const std::string commit = short_commit(at(context, "git_commit")); !commit.empty())
    parts.push_back("commit " + commit);
  std::string cpu = text_of(at(context, "cpu_model"));
  if (const ojson& cores = at(context, "cores"); cores.is_number_integer())
    cpu += (cpu.empty() ? "" : ", ") + text_of(cores) + " cores";
  parts.push_back(cpu);
  parts.push_back(build_text(context));
  if (const ojson& load = at(context, "load_average_1m"); load.is_number())
    parts.push_back("load " + markdown_number(load, 3) + " at the start");
  parts.push_back(wall_text(doc));
  if (!command.empty()) parts.push_back(suite_text(doc));
  std::string out = "Source:";
  bool first = true;
  for (const std::string& p : parts) {
    if (p.empty()) continue;
    out += (first ? " " : " · ") + p;
    first = false;
  }
  out += ".\n";
  if (const ojson& status = at(doc, "status"); status.is_string() && status != "ok")
    out += "\nStatus: **" + escaped(status.get<std::string>()) + "** (see the cases in the result file).\n";
  if (const ojson& warnings = at(context, "warnings"); non_empty_array(warnings))
    out += "\nWarnings recorded: " + text_of(warnings) + ".\n";
  return out;
}

std::string table2_section(const ojson& doc) {
  const ojson& rows = at(doc, "table2");
  if (!non_empty_array(rows)) return "";
  const ojson& reproduction = at(doc, "reproduction");
  const ojson& paper_rows = at(reproduction, "table2");
  // The reproduction block names a row's compression by its label, as the paper does.
  const auto beside = [&paper_rows](const ojson& row) -> const ojson& {
    return find_row(paper_rows, "method", at(row, "method"), "compression", at(row, "compression_label"));
  };
  const auto paper = [&beside](const std::string& key) {
    return [&beside, key](const ojson& row) { return text_of(at(at(beside(row), "paper"), key)); };
  };
  const auto error = [&beside](const std::string& key) {
    return [&beside, key](const ojson& row) { return text_of(at(at(at(beside(row), "ours"), "fidelity"), key)); };
  };
  const bool with_paper = any_cell(rows, paper("N"));
  std::vector<Column> columns{field("method", "method"), field("compression", "compression_label")};
  const auto add = [&](const char* paper_header, const std::string& paper_key, Column ours) {
    if (with_paper) columns.push_back({paper_header, paper(paper_key)});
    columns.push_back(std::move(ours));
  };
  add("paper N", "N", field(with_paper ? "ours N" : "N", "N"));
  add("paper L", "L", field(with_paper ? "ours L" : "L", "L"));
  add("paper I", "I", field(with_paper ? "ours I" : "I", "I"));
  add("paper ms", "total_ms", field(with_paper ? "ours ms" : "ms", "total_ms"));
  add("paper ratio", "time_ratio_vs_plain", field(with_paper ? "ours ratio" : "ratio", "time_ratio_vs_plain"));
  columns.push_back(field("node ratio", "node_ratio"));
  // Only in runs with plain_equal cases: TC-SB against a static body of the nodes it simulates.
  const bool with_equal =
      any_cell(rows, [](const ojson& row) { return text_of(at(row, "time_ratio_vs_equal_plain")); });
  if (with_equal) columns.push_back(field("ratio to equal plain", "time_ratio_vs_equal_plain"));
  columns.push_back(field("nets", "nets"));
  columns.push_back(field("status", "status"));
  const bool with_error = any_cell(rows, error("rms_pct"));
  if (with_error) {
    columns.push_back({"RMS %", error("rms_pct")});
    columns.push_back({"max %", error("max_pct")});
    columns.push_back({"pop max %", error("popping_pct")});
  }
  std::string out = "### Table 2\n\n";
  out += "Mean over nets of N (nodes), L (links), I (interpolations) and the mean step time in ms; ratio: step time "
         "to plain Bullet's, same run.";
  if (with_paper) {
    const std::string hardware = text_of(at(reproduction, "paper_hardware"));
    out += " Paper" + (hardware.empty() ? std::string() : " (" + hardware + ")") + " beside ours.";
  }
  if (with_equal)
    out += " Ratio to equal plain: TC-SB's step time to plain_equal's, a static plain grid of the budget's node count, "
           "same run.";
  if (with_error)
    out += " RMS: error against full-resolution plain Bullet in % of the net's extent, mean over steps and nets; "
           "max and pop: max over steps and nets.";
  return out + "\n\n" + table(columns, rows);
}

/// Per net, TC-SB against plain_equal (the cases' ratio_vs_equal_plain): Table 2 averages the nets, and the tax of
/// adaptivity differs with the net's size. Empty unless the run has plain_equal (and was written since the field).
std::string tax_section(const ojson& doc) {
  ojson rows = ojson::array();
  if (const ojson& cases = at(doc, "cases"); cases.is_array())
    for (const ojson& c : cases)
      if (!text_of(at(c, "ratio_vs_equal_plain")).empty()) rows.push_back(c);
  if (rows.empty()) return "";
  const std::vector<Column> columns{field("case", "label"),
                                    field("N", "mean_nodes"),
                                    field("L", "mean_links"),
                                    {"ms", [](const ojson& c) { return text_of(at(at(c, "step_ms"), "median")); }},
                                    field("ratio to equal plain", "ratio_vs_equal_plain")};
  return "### TC-SB against a static grid of its size, per net\n\nEach TC-SB case's mean nodes and links, its median "
         "step time in ms, and the median over repetitions of its step time to plain_equal's (the same net and "
         "budget, paired by repetition).\n\n" +
         table(columns, rows);
}

std::string table1_section(const ojson& doc) {
  const ojson& rows = at(doc, "table1");
  if (!non_empty_array(rows)) return "";
  const ojson& paper_rows = at(at(doc, "reproduction"), "table1");
  const auto paper_of = [&paper_rows](const ojson& row) -> const ojson& {
    if (!paper_rows.is_array()) return null_json();
    for (const ojson& p : paper_rows) {
      if (at(p, "operation") == at(row, "operation")) return at(p, "paper");
    }
    return null_json();
  };
  const bool with_paper = any_cell(rows, [&](const ojson& row) { return text_of(at(paper_of(row), "N")); });
  std::vector<Column> columns{field("operation", "operation")};
  if (with_paper) columns.push_back({"paper N", [&](const ojson& row) { return text_of(at(paper_of(row), "N")); }});
  columns.push_back(field(with_paper ? "ours N" : "N", "N"));
  if (with_paper)
    columns.push_back({"paper µs", [&](const ojson& row) {
                         return markdown_number(scaled(at(paper_of(row), "complete_ms"), 1000.0));
                       }});
  columns.push_back({with_paper ? "ours µs" : "µs",
                     [](const ojson& row) { return markdown_number(scaled(at(row, "complete_ms"), 1000.0)); }});
  columns.push_back(field("p50 µs", "p50_us"));
  columns.push_back(field("p99 µs", "p99_us"));
  if (with_paper)
    columns.push_back({"paper node %", [&](const ojson& row) {
                         const ojson& p = paper_of(row);
                         return markdown_number(percent_of(at(p, "node_ops_ms"), at(p, "complete_ms")), 3);
                       }});
  columns.push_back(field(with_paper ? "ours node %" : "node %", "node_ops_pct", 3));
  columns.push_back(field("count", "count"));
  return "### Table 1\n\nCost of one operation (mean µs, inside real runs between real steps); N, L: the net's nodes "
         "and links when it ran; node %: share of the time spent on nodes, the rest on links.\n\n" +
         table(columns, rows);
}

/// A fit's slope per 1000 nodes in `unit` (`per_ms` of them in a millisecond): per node it would read 0.0002 ms.
Column slope_column(const std::string& unit, double per_ms) {
  return {unit + " per 1000 nodes", [per_ms](const ojson& row) {
            return markdown_number(scaled(at(row, "slope_ms_per_node"), 1000.0 * per_ms));
          }};
}

Column points_column() {
  return {"points", [](const ojson& row) {
            const ojson& p = at(row, "points");
            return p.is_array() ? std::to_string(p.size()) : std::string();
          }};
}

std::string scaling_section(const ojson& doc) {
  const ojson& scaling = at(doc, "scaling");
  const ojson& steps = at(scaling, "step_ms_vs_nodes");
  const ojson& ops = at(scaling, "op_ms_vs_nodes");
  if (!non_empty_array(steps) && !non_empty_array(ops)) return "";
  std::string out = "### Scaling\n\nLeast-squares lines through one point per net (mean nodes, median step or "
                    "operation time in ms); flatness: how far an operation's cost moves across the nets' sizes.\n";
  if (non_empty_array(steps)) {
    out += "\nStep time against nodes:\n\n" +
           table({field("method", "method"),
                  {"compression", [](const ojson& row) { return compression_text(at(row, "compression")); }},
                  slope_column("ms", 1.0),
                  field("intercept ms", "intercept_ms"),
                  field("r²", "r2"),
                  points_column(),
                  field("valid", "valid")},
                 steps);
  }
  if (non_empty_array(ops)) {
    // An operation costs microseconds: in ms its intercept would need an exponent.
    const Column intercept_us{"intercept µs", [](const ojson& row) {
                                return markdown_number(scaled(at(row, "intercept_ms"), 1000.0));
                              }};
    out += "\nOperations against nodes:\n\n" +
           table({field("operation", "operation"), slope_column("µs", 1000.0), intercept_us, field("r²", "r2"),
                  field("flatness", "flatness"), points_column(), field("valid", "valid")},
                 ops);
  }
  return out;
}

// Claims are rendered generically: the fields known today in a fixed order, then any others in the order they
// first appear, so a claim that gains or loses a field still renders (the claim layout is still evolving).
struct ClaimField {
  const char* key;
  const char* header;
};
constexpr ClaimField kClaimFields[] = {{"id", "id"},
                                       {"comparison", "check"},
                                       {"expected", "expected"},
                                       {"tolerance", "tolerance"},
                                       {"measured", "measured"},
                                       {"interval", "interval"}};
constexpr const char* kClaimFieldsAfterVerdict[] = {"decided"};
// Not columns: prose too long for a table cell, or folded into the verdict column.
constexpr const char* kClaimFieldsLeftOut[] = {"description", "verdict", "pass"};

bool known_claim_field(const std::string& key) {
  for (const ClaimField& f : kClaimFields)
    if (key == f.key) return true;
  for (const char* k : kClaimFieldsAfterVerdict)
    if (key == k) return true;
  for (const char* k : kClaimFieldsLeftOut)
    if (key == k) return true;
  return false;
}

bool any_has(const ojson& claims, const std::string& key) {
  return std::any_of(claims.begin(), claims.end(), [&](const ojson& c) { return c.is_object() && c.contains(key); });
}

std::string verdict_text(const ojson& claim) {
  if (const ojson& v = at(claim, "verdict"); !v.is_null()) return text_of(v);
  if (const ojson& pass = at(claim, "pass"); pass.is_boolean()) return pass.get<bool>() ? "pass" : "FAIL";
  return "";
}

std::string claims_table(const ojson& claims) {
  std::vector<Column> columns;
  for (const ClaimField& f : kClaimFields) {
    if (std::string_view(f.key) == "id" || any_has(claims, f.key)) columns.push_back(field(f.header, f.key));
  }
  columns.push_back({"verdict", verdict_text});
  for (const char* key : kClaimFieldsAfterVerdict) {
    if (any_has(claims, key)) columns.push_back(field(key, key));
  }
  std::vector<std::string> extra;
  for (const ojson& claim : claims) {
    if (!claim.is_object()) continue;
    for (const auto& [key, value] : claim.items()) {
      if (!known_claim_field(key) && std::find(extra.begin(), extra.end(), key) == extra.end()) extra.push_back(key);
    }
  }
  for (const std::string& key : extra) columns.push_back(field(escaped(key), key));
  return table(columns, claims);
}

std::string claims_section(const ojson& doc) {
  const ojson& reproduction = at(doc, "reproduction");
  const ojson& claims = at(reproduction, "claims");
  const ojson& targets = at(reproduction, "targets");
  if (!non_empty_array(claims) && !non_empty_array(targets)) return "";
  std::string out = "### Claims\n\nInterval: where the measured value could lie had the run been repeated "
                    "(percentile bootstrap of the repetitions), when the run has enough repetitions.";
  if (const ojson& v = at(reproduction, "verdict"); !v.is_null()) {
    out += " Verdict of the reproduction: **" + text_of(v) + "**.";
  } else if (const ojson& pass = at(reproduction, "pass"); pass.is_boolean()) {
    out += pass.get<bool>() ? " Every claim of the paper passed." : " At least one claim of the paper **failed**.";
  }
  out += "\n";
  if (non_empty_array(claims)) out += "\nClaims of the paper:\n\n" + claims_table(claims);
  if (non_empty_array(targets)) out += "\nTargets of this project (reported, not gating):\n\n" + claims_table(targets);
  return out;
}

/// A fidelity metric's statistic (`row[metric][stat]`).
Column metric(std::string header, std::string metric_key, std::string stat) {
  return {std::move(header), [metric_key = std::move(metric_key), stat = std::move(stat)](const ojson& row) {
            return markdown_number(at(at(row, metric_key), stat));
          }};
}

/// A Pareto sweep and its maximal compression, of "TC-SB" or "calibrated TC-SB"; empty when neither is there.
std::string sweep_section(const ojson& pareto, const ojson& best, const std::string& label) {
  std::string out;
  if (non_empty_array(pareto)) {
    out += "\nPareto sweep (" + label + " budgets; on front: no other budget is both faster and more accurate):\n\n" +
           table({{"compression", [](const ojson& row) { return compression_text(at(row, "compression")); }},
                  field("N", "N"),
                  field("time ratio", "time_ratio_vs_plain"),
                  field("RMS %", "rms_pct"),
                  field("worst net RMS %", "worst_net_rms_pct"),
                  field("on front", "on_front")},
                 pareto);
  }
  if (best.is_object()) {
    out += "\nMaximum compression" + std::string(label == "TC-SB" ? "" : " of " + label) + ": ";
    const ojson& c = at(best, "compression");
    out += c.is_number() ? compression_text(c) + " of the nodes" : std::string("none");
    out +=
        " keeps the worst net's RMS error within " + markdown_number(at(best, "threshold_pct"), 3) + " % of its extent";
    if (c.is_number())
      out += " (worst net " + markdown_number(at(best, "worst_net_rms_pct")) + " %, time ratio " +
             markdown_number(at(best, "time_ratio_vs_plain")) + ")";
    out += ".";
    // Files written before the mean's figure existed have no such field: nothing is said about it then.
    if (const ojson& mean = at(best, "mean_compression"); best.contains("mean_compression")) {
      out += " On the mean over the nets: ";
      out += mean.is_number() ? compression_text(mean) + " of the nodes" : std::string("none");
      if (mean.is_number())
        out += " (mean RMS " + markdown_number(at(best, "mean_rms_pct")) + " %, time ratio " +
               markdown_number(at(best, "mean_time_ratio_vs_plain")) + ")";
      out += ".";
    }
    out += "\n";
  }
  return out;
}

/// Per net and subject, the error in pixels as the scene's camera sees it, each net's noise floor first; empty
/// unless the run's scene has a camera.
std::string screen_section(const ojson& fidelity) {
  ojson rows = ojson::array();
  for (const ojson& f : at(fidelity, "floors"))
    if (at(f, "noise_floor_screen").is_object())
      rows.push_back({{"net", at(f, "net")}, {"method", "noise floor"}, {"screen", at(f, "noise_floor_screen")}});
  for (const ojson& c : at(fidelity, "cases"))
    if (at(c, "screen").is_object()) rows.push_back(c);
  if (rows.empty()) return "";
  const auto screen = [](std::string header, std::string metric, std::string stat) {
    return Column{std::move(header), [metric = std::move(metric), stat = std::move(stat)](const ojson& row) {
                    return markdown_number(at(at(at(row, "screen"), metric), stat));
                  }};
  };
  const std::vector<Column> columns{
      field("net", "net"),
      field("method", "method"),
      {"compression",
       [](const ojson& row) {
         return at(row, "compression").is_number() ? compression_text(at(row, "compression")) : std::string();
       }},
      screen("mean px", "mean_px", "mean"),
      screen("p95 px", "p95_px", "mean"),
      screen("max px", "max_px", "max"),
      {"steps p95 > 1 px",
       [](const ojson& row) { return markdown_number(at(at(row, "screen"), "p95_over_1px_share")); }},
      {"in view", [](const ojson& row) { return markdown_number(at(at(row, "screen"), "points_in_view"), 0); }},
      field("status", "status")};
  return "\nError in pixels as the camera sees it: per step, over the grid points the reference shows in view, the "
         "mean, p95 and maximum distance on the image between the reference's point and the subject's; then the mean "
         "over the steps (max px: the maximum); the share of steps whose p95 exceeds one pixel; grid points in view "
         "per step.\n\n" +
         table(columns, rows);
}

std::string fidelity_section(const ojson& doc) {
  const ojson& fidelity = at(doc, "fidelity");
  const ojson& rows = at(fidelity, "rows");
  const ojson& pareto = at(doc, "pareto");
  const ojson& best = at(doc, "max_compression");
  if (!non_empty_array(rows) && !non_empty_array(pareto) && !best.is_object()) return "";
  std::string out = "### Fidelity\n\nError against full-resolution plain Bullet, in % of the net's extent (energy "
                    "drift: in % of the reference's initial energy); rows combine nets as mean of means and p95s, max "
                    "of maxima. Time ratio: the subject's mean step to the reference's, both timed in the fidelity "
                    "pass.\n";
  if (non_empty_array(rows)) {
    std::vector<Column> columns{field("method", "method"), {"compression", [](const ojson& row) {
                                                              return compression_text(at(row, "compression"));
                                                            }}};
    if (any_cell(rows, [](const ojson& row) { return text_of(at(row, "grid")); }))
      columns.push_back(field("grid", "grid"));
    if (any_cell(rows, [](const ojson& row) { return text_of(at(row, "solver_divisor")); }))
      columns.push_back(field("passes ÷", "solver_divisor"));
    for (Column c : {field("N", "N"), metric("RMS % mean", "rms_pct", "mean"), metric("RMS % p95", "rms_pct", "p95"),
                     metric("max %", "max_pct", "max"), metric("weighted RMS %", "weighted_rms_pct", "mean"),
                     metric("pop max %", "popping_pct", "max"), metric("energy drift %", "energy_drift_pct", "mean"),
                     field("time ratio", "time_ratio_vs_plain"), field("switch ms", "switch_ms"),
                     field("worst net RMS %", "worst_net_rms_pct"), field("nets", "nets"), field("status", "status")})
      columns.push_back(std::move(c));
    out += "\n" + table(columns, rows);
  }
  out += screen_section(fidelity);
  out += sweep_section(pareto, best, "TC-SB");
  out += equal_error_section(doc);
  out += sweep_section(at(doc, "pareto_calibrated"), at(doc, "max_compression_calibrated"), "calibrated TC-SB");
  // A reproduction lists these targets with the claims; a plain run with a fidelity pass has them only here.
  if (const ojson& targets = at(fidelity, "targets"); non_empty_array(targets) && !at(doc, "reproduction").is_object())
    out += "\nFidelity targets of this project (reported, not gating):\n\n" + claims_table(targets);
  return out;
}

/// A scene of many bodies: each method of the world pass in one table (world/world_runner.h).
std::string world_section(const ojson& doc) {
  const ojson& world = at(doc, "world");
  const ojson& methods = at(world, "methods");
  if (!non_empty_array(methods)) return "";
  std::string out = "### Many bodies\n\n" + text_of(at(world, "bodies")) + " bodies, " +
                    text_of(at(world, "scene_nodes")) +
                    " nodes at full resolution, stepped side by side in one world each. p95 px: the 95th percentile of "
                    "the pixel error over every point of every body the camera sees, mean over steps; time / full: the "
                    "median over blocks of the step's ratio to full resolution's; pop: the largest jump on the image "
                    "where a body changed its resolution.\n";
  const std::vector<Column> columns{{"method",
                                     [](const ojson& row) {
                                       const ojson& divisor = at(row, "solver_divisor");
                                       return text_of(at(row, "method")) +
                                              (divisor.is_number() ? " ÷" + text_of(divisor) : std::string());
                                     }},
                                    {"budget", [](const ojson& row) { return compression_text(at(row, "budget")); }},
                                    field("mean nodes", "mean_nodes"),
                                    field("step ms", "step_ms"),
                                    field("boundary ms", "boundary_ms"),
                                    field("time / full", "step_ratio"),
                                    field("p95 px", "p95_px"),
                                    field("pop max px", "popping_px"),
                                    field("resolution changes", "resolution_changes"),
                                    field("status", "status")};
  return out + "\n" + table(columns, methods) + world_equal_error_section(doc);
}

/// A run of a suite with axes: each configuration's Table 2, Table 1 and fits under a line naming it (the run-wide
/// tables are empty then: a mean over configurations would mix settings).
std::string configurations_section(const ojson& doc) {
  const ojson& configurations = at(doc, "configurations");
  if (!non_empty_array(configurations)) return "";
  std::string out;
  for (const ojson& c : configurations) {
    const ojson tables = {{"table2", at(c, "table2")}, {"table1", at(c, "table1")}, {"scaling", at(c, "scaling")}};
    out += "\n### Configuration " + text_of(at(c, "label")) + "\n";
    for (const std::string& section : {table2_section(tables), table1_section(tables), scaling_section(tables)})
      if (!section.empty()) out += "\n" + section;
  }
  return out;
}

}  // namespace

std::string markdown_report(const ojson& native) {
  std::string out = heading(native) + "\n" + source_line(native);
  for (const std::string& section :
       {table2_section(native), tax_section(native), table1_section(native), scaling_section(native),
        configurations_section(native), fidelity_section(native), world_section(native), claims_section(native)}) {
    if (!section.empty()) out += "\n" + section;
  }
  return out;
}

std::string MarkdownFormat::render_native(const ojson& native) const { return markdown_report(native); }

}  // namespace tcsb
