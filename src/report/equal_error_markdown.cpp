#include "report/equal_error_markdown.h"

#include <optional>

#include "base/case_pairing.h"
#include "report/markdown_table.h"

namespace tcsb {

using namespace markdown;

namespace {

/// The headline's budget: the and the tables' 30 %.
constexpr double kHeadlineBudget = 0.3;

const ojson& equal_error_nets(const ojson& doc) { return at(at(at(doc, "fidelity"), "equal_error"), "nets"); }

std::string unit_of(const ojson& net) {
  return text_of(at(net, "metric")) == "p95_px" ? std::string("p95 px") : std::string("RMS %");
}

/// "2.31× (1.9–2.6)", "≤ 0.8× (at its cheapest)", "not reached", or "" for a missing rival.
std::string speedup_text(const ojson& rival) {
  const std::string status = text_of(at(rival, "status"));
  if (status == "not_reached") return "not reached";
  const std::string s = markdown_number(at(rival, "speedup"), 3);
  if (s.empty()) return "";
  if (status == "at_cheapest") return "≤ " + s + "× (its cheapest point is as accurate)";
  const ojson& interval = at(rival, "interval");
  if (interval.is_array() && interval.size() == 2)
    return s + "× (" + markdown_number(interval[0], 3) + "–" + markdown_number(interval[1], 3) + ")";
  return s + "×";
}

/// The net the headline shows: the one with the most nodes (the last of equal size), whose rows are computed.
const ojson* headline_net(const ojson& doc) {
  const ojson* best = nullptr;
  double best_nodes = -1;
  for (const ojson& net : equal_error_nets(doc)) {
    double nodes = 0;
    for (const ojson& n : at(at(doc, "suite"), "nets"))
      if (at(n, "name") == at(net, "net") && at(n, "nodes").is_number()) nodes = at(n, "nodes").get<double>();
    if (nodes >= best_nodes) {
      best = &net;
      best_nodes = nodes;
    }
  }
  return best;
}

const ojson* row_at(const ojson& net, double compression) {
  for (const ojson& row : at(net, "rows"))
    if (at(row, "compression").is_number() && same_compression(at(row, "compression").get<double>(), compression))
      return &row;
  return nullptr;
}

/// What the headline reads of a run: the curves of the net it shows and the rival a user would pick instead of
/// TC-SB — the uniform grid for one body, discrete LOD for a scene of many bodies (the world pass's whole scene).
struct HeadlineCurves {
  const ojson* net = nullptr;
  std::string rival;       ///< the rows' key
  std::string rival_name;  ///< as the verdict names it
  std::string curve_name;  ///< its curve, as the verdict names it
  std::string never;       ///< the verdict's reason when TC-SB's error never falls on that curve
};

HeadlineCurves headline_curves(const ojson& doc) {
  const ojson& world = at(at(doc, "world"), "equal_error");
  if (world.is_object())
    return {&at(world, "scene"), "discrete_lod", "discrete LOD", "discrete LOD's curve",
            "discrete LOD's curve (at each, its cheapest budget errs as little or less, or none is as accurate): no "
            "speed-up against it"};
  return {headline_net(doc), "uniform_grid", "the best uniform grid", "the grids' curve",
          "the uniform grids' curve (at each, the cheapest grid errs as little or less, or no grid is as accurate): "
          "no speed-up against them"};
}

/// The row of the largest interpolated speed-up against the rival; nullptr when none is interpolated.
const ojson* best_rival_row(const ojson& net, const std::string& rival) {
  const ojson* best = nullptr;
  for (const ojson& row : at(net, "rows")) {
    const ojson& r = at(row, rival);
    if (text_of(at(r, "status")) != "interpolated" || !at(r, "speedup").is_number()) continue;
    if (!best || at(r, "speedup").get<double>() > at(at(*best, rival), "speedup").get<double>()) best = &row;
  }
  return best;
}

/// What steers the scene's detail, from the suite's settings: the viewer, wind, contact, or motion alone.
std::string decided_by(const ojson& suite) {
  std::string out;
  const auto add = [&](const char* what) { out += (out.empty() ? "" : ", ") + std::string(what); };
  if (at(at(suite, "feedback"), "view") == true) add("viewer");
  if (at(at(suite, "scene"), "wind").is_object()) add("wind");
  if (non_empty_array(at(at(suite, "scene"), "colliders"))) add("contact");
  if (out.empty()) add("motion");
  return out;
}

std::string model_of(const ojson& suite) {
  const ojson& model = at(at(suite, "material"), "model");
  return model.is_string() ? model.get<std::string>() : std::string("bullet");
}

std::string curve_text(const ojson& points, const std::string& unit) {
  std::string out;
  for (const ojson& p : points) {
    std::string label = text_of(at(p, "method"));
    if (label == "full_resolution")
      label = "÷" + text_of(at(p, "solver_divisor"));
    else if (label != "reference")
      label = compression_text(at(p, "compression"));
    out += (out.empty() ? "" : "; ") + label + ": " + markdown_number(at(p, "time_ms"), 3) + " ms, " +
           markdown_number(at(p, "error"), 3) + " " + unit;
  }
  return out;
}

/// One net's (or the world pass's scene's) table and curves; `grid_rival` names the grid-like rival's key.
std::string net_equal_error_text(const ojson& net, const std::string& grid_rival, const std::string& grid_title) {
  const std::string unit = unit_of(net);
  std::string out = "\n";  // (one append per piece: GCC 12 -Wrestrict false positive on a chain starting at a literal)
  out += text_of(at(net, "net")) + " (error: " + unit + ", noise floor " + markdown_number(at(net, "floor"), 3) + "):";
  if (at(net, "missing").is_string()) return out + " no speed-up: " + text_of(at(net, "missing")) + ".\n";
  out += "\n\n" + table({{"budget", [](const ojson& r) { return compression_text(at(r, "compression")); }},
                         field("N", "N"),
                         field("TC-SB ms", "time_ms", 3),
                         field("TC-SB " + unit, "error", 3),
                         {grid_title, [grid_rival](const ojson& r) { return speedup_text(at(r, grid_rival)); }},
                         {"vs full resolution", [](const ojson& r) { return speedup_text(at(r, "full_resolution")); }}},
                        at(net, "rows"));
  const ojson& curves = at(net, "curves");
  const ojson& monotone = at(curves, "monotone");
  for (const std::string& name : {std::string("tcsb"), grid_rival, std::string("full_resolution")})
    out += "\n- curve " + name + (at(monotone, name) == false ? " (not monotone)" : "") + ": " +
           curve_text(at(curves, name), unit);
  return out + "\n";
}

}  // namespace

std::string equal_error_section(const ojson& doc) {
  const ojson& block = at(at(doc, "fidelity"), "equal_error");
  if (!block.is_object()) return "";
  std::string out =
      "\n### Speed-up at equal error\n\nFor the error TC-SB reaches at each budget, the step time each rival needs "
      "to reach it on its curve of error against time (log-log interpolation, never extrapolated), as a ratio to "
      "TC-SB's step; 95 % intervals over the pass's interleaved blocks. Uniform grid: the grids of every budget "
      "with full resolution as the finest; full resolution: the suite's passes a step divided by 2, 4 and 8, with "
      "the reference as the finest (its error is the noise floor).\n";
  for (const ojson& net : at(block, "nets")) out += net_equal_error_text(net, "uniform_grid", "vs uniform grid");
  return out;
}

std::string world_equal_error_section(const ojson& doc) {
  const ojson& block = at(at(doc, "world"), "equal_error");
  if (!block.is_object()) return "";
  std::string out =
      "\n#### Many bodies: speed-up at equal error\n\nFor the p95 px TC-SB under one world budget reaches at each "
      "budget, the step time of the whole scene each rival needs to reach it on its curve of p95 px against step time "
      "(log-log interpolation, never extrapolated), as a ratio to TC-SB's; 95 % intervals over the pass's "
      "interleaved blocks. Discrete LOD: its fitted levels at every budget; full resolution: the suite's passes a "
      "step divided by each divisor; the reference, at the noise floor, is both rivals' finest point.\n";
  out += net_equal_error_text(at(block, "scene"), "discrete_lod", "vs discrete LOD");
  out += "\nThe world budget against per-body budgets at the same total node count: per-body TC-SB's p95 px at the "
         "world budget's mean nodes, log-log between its two budgets around them (\"outside\": its budgets do not "
         "reach that count); above 1, the world budget errs less.\n\n";
  return out + table({{"budget", [](const ojson& r) { return compression_text(at(r, "budget")); }},
                      field("N", "N"),
                      field("world p95 px", "tcsb_world_p95_px", 3),
                      {"per-body p95 px",
                       [](const ojson& r) {
                         const std::string v = markdown_number(at(r, "tcsb_body_p95_px"), 3);
                         return v.empty() ? std::string("outside") : v;
                       }},
                      field("per-body / world", "body_over_world", 3)},
                     at(block, "same_nodes"));
}

std::string HeadlineRowFormat::render_native(const ojson& doc) const {
  const ojson& suite = at(doc, "suite");
  std::string row =
      "| " + escaped(text_of(at(suite, "name"))) + " | " + model_of(suite) + " | " + decided_by(suite) + " | ";
  const HeadlineCurves curves = headline_curves(doc);
  const ojson* net = curves.net;
  if (!net || net->is_null()) return row + "no curves: the suite has no fidelity.curves | | | | |\n";
  const std::string unit = unit_of(*net);
  row += escaped(text_of(at(*net, "net"))) + ", " + unit;
  if (curves.rival != "uniform_grid") row += ", vs " + curves.rival_name;
  row += " | ";
  if (at(*net, "missing").is_string())
    return row + "no speed-up: " + escaped(text_of(at(*net, "missing"))) + " | | | |\n";
  if (const ojson* r = row_at(*net, kHeadlineBudget))
    row += markdown_number(at(*r, "time_ms"), 3) + " ms, " + markdown_number(at(*r, "error"), 3) + " | " +
           speedup_text(at(*r, curves.rival)) + " | " + speedup_text(at(*r, "full_resolution")) + " | ";
  else
    row += "no 30 % budget | | | ";
  const ojson* best = best_rival_row(*net, curves.rival);
  row += best ? speedup_text(at(*best, curves.rival)) + " at " + compression_text(at(*best, "compression"))
              : std::string("never interpolated");
  return row + " |\n";
}

std::string HeadlineVerdictFormat::render_native(const ojson& doc) const {
  const ojson& suite = at(doc, "suite");
  std::string line = "- **" + text_of(at(suite, "name")) + "** (" + model_of(suite) + "): ";
  const HeadlineCurves curves = headline_curves(doc);
  const ojson* net = curves.net;
  if (!net || net->is_null() || at(*net, "missing").is_string()) return line + "no speed-up could be computed.\n";
  const ojson* best = best_rival_row(*net, curves.rival);
  if (!best) return line + "at no budget does TC-SB's error fall on " + curves.never + ".\n";
  const ojson& rival = at(*best, curves.rival);
  const double s = at(rival, "speedup").get<double>();
  const std::string target = markdown_number(ojson(kHeadlineSpeedup), 2) + "×";
  line += "its largest speed-up against " + curves.rival_name + " is " + speedup_text(rival) + ", at " +
          compression_text(at(*best, "compression"));
  // Read off a curve that is not monotone, the first crossing can start at a point a cheaper one beats: say so.
  if (at(at(at(*net, "curves"), "monotone"), curves.rival) == false)
    line += " (" + curves.curve_name + " is not monotone)";
  // Three verdicts on the interval, as every claim here: decided only where the whole interval is on one side.
  const ojson& interval = at(rival, "interval");
  const bool has_interval = interval.is_array() && interval.size() == 2 && interval[0].is_number();
  if (has_interval && interval[0].get<double>() >= kHeadlineSpeedup) return line + ": reaches " + target + ".\n";
  if (has_interval && interval[1].get<double>() < kHeadlineSpeedup)
    return line + ": short of " + target + " by a factor of " + markdown_number(ojson(kHeadlineSpeedup / s), 3) + ".\n";
  return line + ": undecided, its interval spans " + target + ".\n";
}

}  // namespace tcsb
