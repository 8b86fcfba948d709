// Suite parsing and validation: every key, type and range is checked before anything runs, so a bad suite fails in
// milliseconds with one line naming the file and the field instead of hours into a run. This file reads the suite's
// shape, its nets and methods, and checks settings against each other; the scalar settings are read through their
// table (suite_settings_table.h), and the material, fidelity and scene blocks have files of their own.
#include "suite/suite.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "base/json_file.h"
#include "base/sha256.h"
#include "suite/calibration_path.h"
#include "suite/case_plan.h"
#include "suite/fidelity_block.h"
#include "suite/material_block.h"
#include "suite/scene_block.h"
#include "suite/scene_bodies.h"
#include "suite/suite_axes.h"
#include "suite/suite_fields.h"
#include "suite/suite_memory.h"
#include "suite/suite_settings_table.h"

namespace tcsb {
namespace {

using namespace suite_fields;

/// "pinned": {"edge": "min_z"} or {"nodes": [[x, z], ...]} (exactly one of the two), into `net`, whose width and
/// height are read already: a node off the grid, a listed node twice or an empty list is an error.
void parse_pinned_beyond_corners(const Reader& r, const json& j, const std::string& path, NetSpec& net) {
  const Object o(r, j, path, {"edge", "nodes"});
  if (j.size() != 1) r.fail(path, "must have exactly one of \"edge\" or \"nodes\", got " + j.dump());
  if (const json* edge = o.find("edge")) {
    net.pinned_edges = r.choice<unsigned>(
        *edge, o.at("edge"), {{"min_x", kEdgeMinX}, {"max_x", kEdgeMaxX}, {"min_z", kEdgeMinZ}, {"max_z", kEdgeMaxZ}});
    return;
  }
  const json& nodes = o.need("nodes");
  r.array(nodes, o.at("nodes"));  // empty: rejected (no pins is "none")
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::string at = index_path(o.at("nodes"), i);
    if (!nodes[i].is_array() || nodes[i].size() != 2)
      r.fail(at, "must be a grid node [x, z], got " + describe(nodes[i]));
    const GridNode n{static_cast<int>(r.integer(nodes[i][0], index_path(at, 0), 0, net.width - 1)),
                     static_cast<int>(r.integer(nodes[i][1], index_path(at, 1), 0, net.height - 1))};
    if (std::find(net.pinned_nodes.begin(), net.pinned_nodes.end(), n) != net.pinned_nodes.end())
      r.fail(at, "duplicate node " + nodes[i].dump());
    net.pinned_nodes.push_back(n);
  }
}

NetSpec parse_net(const Reader& r, const json& j, const std::string& path) {
  const Object o(r, j, path, {"name", "width", "height", "size", "elevation", "mass", "pinned", "shear", "bend"});
  NetSpec net;
  net.name = r.string(o.need("name"), o.at("name"));
  if (net.name.empty() || net.name.find('/') != std::string::npos) {
    r.fail(o.at("name"), "must be a non-empty name without '/', got " + describe(o.need("name")));
  }
  o.read("width", net.width, 2, 100000, true);
  o.read("height", net.height, 2, 100000, true);
  if (const json* size = o.find("size")) {
    const std::array<double, 2> xz = r.numbers<2>(*size, o.at("size"), kSceneLength);
    net.size_x = xz[0];
    net.size_z = xz[1];
  }
  o.read("elevation", net.elevation, kSceneCoordinate);  // what Bullet's floats can carry (suite_fields.h)
  if (const json* mass = o.find("mass")) {
    const Object m(r, *mass, o.at("mass"), {"total", "per_node"});
    if (mass->size() != 1) {
      r.fail(o.at("mass"), "must have exactly one of \"total\" or \"per_node\", got " + mass->dump());
    }
    net.mass_mode = mass->contains("total") ? MassMode::kTotal : MassMode::kPerNode;
    m.read(net.mass_mode == MassMode::kTotal ? "total" : "per_node", net.mass, kSceneQuantity);
  }
  if (const json* pinned = o.find("pinned")) {
    const std::string p = o.at("pinned");
    if (pinned->is_array()) {
      net.pinned_corners = 0;
      for (std::size_t i = 0; i < pinned->size(); ++i) {
        const unsigned bit = r.choice<unsigned>((*pinned)[i], index_path(p, i),
                                                {{"min_min", kCornerMinMin},
                                                 {"max_min", kCornerMaxMin},
                                                 {"min_max", kCornerMinMax},
                                                 {"max_max", kCornerMaxMax}});
        if (net.pinned_corners & bit) r.fail(index_path(p, i), "duplicate corner " + (*pinned)[i].dump());
        net.pinned_corners |= bit;
      }
    } else if (pinned->is_string()) {
      net.pinned_corners = r.choice<unsigned>(*pinned, p, {{"corners", kAllCorners}, {"none", 0u}});
    } else if (pinned->is_object()) {
      net.pinned_corners = 0;
      parse_pinned_beyond_corners(r, *pinned, p, net);
    } else {
      r.fail(p,
             "must be \"corners\", \"none\", a list of corners, {\"edge\": ...} or {\"nodes\": [[x, z], ...]}, got " +
                 describe(*pinned));
    }
  }
  o.read("shear", net.shear_links);
  o.read("bend", net.bend_links);
  return net;
}

/// The root's keys: the structured blocks around the table's root settings and sections (suite_settings_table.h).
std::vector<std::string_view> root_keys() {
  std::vector<std::string_view> keys = {"name", "description", "nets", "methods", "compression"};
  for (const std::string_view key : suite_setting_keys("")) keys.push_back(key);
  keys.insert(keys.end(), {"solver", "tcsb", "feedback", "fidelity", "axes", "scene", "material"});
  return keys;
}

/// The table's sections: solver is required, tcsb and feedback optional.
void parse_sections(const Reader& r, const Object& root, Suite& s) {
  for (const char* section : {"solver", "tcsb", "feedback"}) {
    const json* j = root.find(section, std::string_view(section) == "solver");
    if (!j) continue;
    read_suite_settings(r, Object(r, *j, section, suite_setting_keys(section)), section, s);
  }
}

void check_memory(const Suite& suite, const Reader& r) {
  const std::optional<MemoryShortfall> shortfall = memory_shortfall(suite);
  if (!shortfall) return;
  const std::string budget = " needs about " + format_bytes(shortfall->needed) + ", but only " +
                             format_bytes(shortfall->usable) + " may be used (80% of the headroom under " +
                             shortfall->headroom.source + ", " +
                             format_bytes(static_cast<double>(shortfall->headroom.bytes)) + ")";
  if (shortfall->recorder && !suite.axes.empty()) {
    // The axes multiply the cases (and may vary the steps): they make the recorder large.
    r.fail("axes", "recording every step of " + std::to_string(expand_cases(suite).size()) + " cases (" +
                       std::to_string(suite.configurations.size()) + " configurations) x " +
                       std::to_string(suite.repetitions) + " repetitions" + budget);
  }
  if (shortfall->recorder) {
    // Blame the field that makes it large: a huge "steps" is not the net's fault.
    r.fail("steps", "recording " + std::to_string(suite.steps) + " steps (+ " + std::to_string(suite.warmup_steps) +
                        " warm-up) x " + std::to_string(expand_cases(suite).size()) + " cases x " +
                        std::to_string(suite.repetitions) + " repetitions" + budget);
  }
  if (sdf_cells(suite.scene) > 0) {
    // The colliders' distance field is what a fine voxel makes large: without it the suite may fit.
    Suite without_field = suite;
    without_field.scene.rigid_contact = false;
    if (!memory_shortfall(without_field))
      r.fail("scene.sdf_voxel", "the colliders' distance field at " + fmt_number(suite.scene.sdf_voxel) +
                                    " m voxels (up to " +
                                    std::to_string(static_cast<long long>(sdf_cells(suite.scene))) +
                                    " cells of 3^3 voxels in each body's world)" + budget);
  }
  if (suite.interleave_across_nets) {
    // The sum over the nets is too much, but one net at a time may fit: then the field is what to change.
    Suite one_net_at_a_time = suite;
    one_net_at_a_time.interleave_across_nets = false;
    if (!memory_shortfall(one_net_at_a_time))
      r.fail("interleave_across_nets", "every net's bodies alive at once" + budget);
  }
  const NetSpec& net = suite.nets[shortfall->net];
  const std::string size = std::to_string(net.width) + " x " + std::to_string(net.height) + " = " +
                           std::to_string(net.node_count()) + " nodes";
  r.fail(index_path("nets", shortfall->net),
         "net \"" + net.name + "\" (" + size + ") with all methods' bodies alive" + budget);
}

bool suite_runs_method(const Suite& s, Method m) {
  return std::find(s.methods.begin(), s.methods.end(), m) != s.methods.end();
}

/// The suite's "nets", each parsed and named once; the array itself, which the material block reads again.
const json& parse_nets(const Reader& r, const Object& root, Suite& s) {
  const json& nets = r.array(root.need("nets"), "nets");
  std::map<std::string, std::size_t> net_names;  // not a scan per net: a file may list 10^5 of them
  for (std::size_t i = 0; i < nets.size(); ++i) {
    s.nets.push_back(parse_net(r, nets[i], index_path("nets", i)));
    if (const auto [it, fresh] = net_names.emplace(s.nets[i].name, i); !fresh)
      r.fail(index_path("nets", i) + ".name",
             "duplicate net name \"" + s.nets[i].name + "\" (also nets[" + std::to_string(it->second) + "])");
  }
  return nets;
}

/// The suite's "methods" and the "compression" targets they run at.
void parse_methods(const Reader& r, const Object& root, Suite& s) {
  const json& methods = r.array(root.need("methods"), "methods");
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const Method m = r.choice<Method>(methods[i], index_path("methods", i),
                                      {{"plain", Method::kPlain},
                                       {"bullet_patch", Method::kBulletPatch},
                                       {"tcsb", Method::kTcsb},
                                       {"plain_equal", Method::kPlainEqual},
                                       {"stock", Method::kStock}});
    if (std::find(s.methods.begin(), s.methods.end(), m) != s.methods.end()) {
      r.fail(index_path("methods", i), "duplicate method \"" + std::string(method_name(m)) + "\"");
    }
    s.methods.push_back(m);
  }
  const bool has_tcsb = suite_runs_method(s, Method::kTcsb);
  const bool has_equal = suite_runs_method(s, Method::kPlainEqual);
  if (const json* compression = root.find("compression", has_tcsb || has_equal)) {
    if (!has_tcsb && !has_equal)
      r.fail("compression", "only allowed when methods contains \"tcsb\" or \"plain_equal\"");
    r.array(*compression, "compression");
    std::set<double> targets;  // not a scan per target: a file may list 10^6 of them
    for (std::size_t i = 0; i < compression->size(); ++i) {
      const double c = r.number((*compression)[i], index_path("compression", i), kFraction);
      if (!targets.insert(c).second)
        r.fail(index_path("compression", i), "duplicate compression target " + fmt_number(c));
      s.compression.push_back(c);
    }
  }
  // plain_equal is sized by the budgets below 1 (at 1 it would be the plain body): with none it would run nothing,
  // and silently measuring nothing would look like a result.
  if (has_equal && std::none_of(s.compression.begin(), s.compression.end(), [](double c) { return c < 1.0; })) {
    const auto at = std::find(s.methods.begin(), s.methods.end(), Method::kPlainEqual) - s.methods.begin();
    r.fail(index_path("methods", static_cast<std::size_t>(at)),
           "plain_equal needs a compression target below 1 (it runs one case per such target)");
  }
}

/// Settings that do something only together with another: one without its partner is a mistake.
void check_settings_together(const Reader& r, const Suite& s) {
  // The tension only weighs the interface charge, and the pull acts through the tension: without what it needs (set,
  // or varied by an axis) each would do nothing.
  const auto set_or_varied = [&](double value, const std::string& path) {
    return value > 0 || std::any_of(s.axes.begin(), s.axes.end(), [&](const Axis& a) { return a.path == path; });
  };
  if (s.feedback.interface_tension > 0 && !set_or_varied(s.feedback.interface_charge, "feedback.interface_charge"))
    r.fail("feedback.interface_tension", "weighs the interface charge, which is 0 here: set feedback.interface_charge");
  if (s.feedback.pin_level_pull > 0 && !set_or_varied(s.feedback.interface_tension, "feedback.interface_tension"))
    r.fail("feedback.pin_level_pull", "acts through the pin tension, which is 0 here: set feedback.interface_tension");
  const bool view_in_an_axis = std::any_of(s.axes.begin(), s.axes.end(), [](const Axis& a) {
    return a.path == "feedback.view" && std::find(a.values.begin(), a.values.end(), json(true)) != a.values.end();
  });
  // A pin path moves the pins: on a net without any it would do nothing, and silently doing nothing looks like a scene.
  if (s.scene.pin_path.moves())
    for (std::size_t k = 0; k < s.nets.size(); ++k) {
      const NetSpec& n = s.nets[k];
      if (n.pinned_corners == 0 && n.pinned_edges == 0 && n.pinned_nodes.empty())
        r.fail("scene.pin_path", "moves the nets' pins, but net \"" + n.name + "\" (nets[" + std::to_string(k) +
                                     "]) has none (its \"pinned\" is \"none\")");
    }
  if ((s.feedback.view || view_in_an_axis) && !s.scene.camera)
    r.fail("feedback.view", "the view terms see through the scene's camera: set scene.camera");
}

/// What each method can build, and what the wind needs, from the nets' link kinds.
void check_link_kinds(const Reader& r, const Suite& s) {
  // CreatePatch makes structural links (and, with gendiags, one diagonal per cell), never our shear/bend sets; the
  // TreeCut soft body's balanced-cut adjacency is the 4-neighbourhood, so it is structural-only too (the paper's
  // net: L ~ 2N).
  for (std::size_t i = 0; i < s.methods.size(); ++i) {
    if (s.methods[i] != Method::kBulletPatch && s.methods[i] != Method::kTcsb) continue;
    const char* why = s.methods[i] == Method::kTcsb ? "; TC-SB supports structural links only"
                                                    : "; CreatePatch makes structural links only";
    for (std::size_t k = 0; k < s.nets.size(); ++k) {
      const NetSpec& n = s.nets[k];
      if (!n.shear_links && !n.bend_links) continue;
      r.fail(index_path("methods", i), std::string(method_name(s.methods[i])) + " cannot build net \"" + n.name +
                                           "\" (nets[" + std::to_string(k) + "]) with " +
                                           (n.shear_links ? "shear" : "bend") + " links" + why);
    }
  }
  // A windy scene gives every body the faces of its grid cells (SceneWorld::attach), found from its structural links.
  if (s.scene.wind)
    for (std::size_t k = 0; k < s.nets.size(); ++k)
      if (s.nets[k].shear_links || s.nets[k].bend_links)
        r.fail("scene.wind",
               "needs nets of structural links only (their cells become the faces the wind pushes); net \"" +
                   s.nets[k].name + "\" (nets[" + std::to_string(k) + "]) has " +
                   (s.nets[k].shear_links ? "shear" : "bend") + " links");
}

/// What the fidelity pass needs of the suite.
void check_fidelity(const Reader& r, const Suite& s) {
  const bool has_tcsb = suite_runs_method(s, Method::kTcsb);
  // The fidelity pass compares TC-SB (and the ablations at TC-SB's targets) with the reference: without TC-SB there
  // is nothing to measure, and silently measuring nothing would look like a pass.
  if (s.fidelity.enabled && !has_tcsb) r.fail("fidelity.enabled", "requires methods to contain \"tcsb\"");
  // The fidelity pass runs once per net with the suite's settings, after the timed cases; per configuration it is
  // not built (yet), and running it with the base settings beside cases of other settings would mislead.
  if (s.fidelity.enabled && !s.axes.empty()) r.fail("fidelity.enabled", "cannot be combined with axes");
}

/// The calibration fidelity.calibration names, read and checked against the suite.
void read_calibration(const Reader& r, const std::string& file, Suite& s) {
  if (s.fidelity.calibration_path.empty()) return;
  if (!suite_runs_method(s, Method::kTcsb)) r.fail("fidelity.calibration", "requires methods to contain \"tcsb\"");
  // Relative to the suite file, so a suite and its calibration travel together (and never outside its tree).
  const std::filesystem::path path = calibration_file_path(file, s.fidelity.calibration_path);
  Calibration c = parse_calibration_file(path);
  if (const std::string why = calibration_mismatch(c, s); !why.empty())
    r.fail("fidelity.calibration", path.string() + " does not fit this suite: " + why);
  s.calibration = std::move(c);
}

}  // namespace

const char* method_name(Method method) {
  switch (method) {
    case Method::kPlain: return "plain";
    case Method::kBulletPatch: return "bullet_patch";
    case Method::kTcsb: return "tcsb";
    case Method::kPlainEqual: return "plain_equal";
    case Method::kStock: return "stock";
  }
  return "unknown";
}

Suite parse_suite_text(const std::string& text, const std::string& file, const SuiteAdjustment& adjust) {
  const Reader r(file);
  const json doc = parse_json_text<json>(text, file);
  if (!doc.is_object()) r.fail("", "the suite must be a JSON object, got " + describe(doc));
  const std::vector<std::string_view> keys = root_keys();
  const Object root(r, doc, "", keys);
  Suite s;
  s.path = file;
  s.sha256 = sha256_hex(text);
  s.source = text;
  s.name = r.string(root.need("name"), "name");
  if (s.name.empty()) r.fail("name", "must not be empty");
  if (const json* d = root.find("description")) s.description = r.string(*d, "description");

  const json& nets = parse_nets(r, root, s);
  parse_methods(r, root, s);
  read_suite_settings(r, root, "", s);
  if (s.interleave_across_nets && s.interleave_steps == 0)
    r.fail("interleave_across_nets", "needs interleave_steps above 0 (the cases take turns only side by side)");
  parse_material(r, root, nets, s);
  parse_sections(r, root, s);
  parse_fidelity(r, root, s);
  if (const json* scene = root.find("scene")) s.scene = parse_scene(r, *scene);
  if (const json* axes = root.find("axes")) parse_axes(r, *axes, s);
  check_settings_together(r, s);
  check_link_kinds(r, s);
  check_fidelity(r, s);
  check_scene_bodies(r, s);
  if (adjust) adjust(s);  // before the memory check: it must see the suite that will run
  // Counted before anything expands them (the memory check does): 10^8 cases would exhaust memory on the way.
  if (const std::uint64_t cases = case_count(s); cases > kMaxCases)
    r.fail(s.axes.empty() ? "nets" : "axes",
           std::to_string(configuration_count(s)) + " configuration(s) x " + std::to_string(s.nets.size()) +
               " net(s) x their methods and compression targets = " + std::to_string(cases) + " cases, more than the " +
               std::to_string(kMaxCases) + " a suite may have");
  check_material(r, s);  // (before the calibration is read: the compliant material refuses one)
  read_calibration(r, file, s);
  check_memory(s, r);
  return s;
}

Suite parse_suite(const std::filesystem::path& path, const SuiteAdjustment& adjust) {
  Suite suite = parse_suite_text(read_input_file(path, kSuiteJsonLimits.max_bytes), path.string(), adjust);
  suite.path = path;
  return suite;
}

}  // namespace tcsb
