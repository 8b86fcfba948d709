// Suite parsing and validation: every key, type and range is checked here, before anything runs, so a bad suite
// fails in milliseconds with one line naming the file and the field instead of hours into a run.
#include "harness/suite.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>
#include <utility>

#include "harness/case_plan.h"
#include "harness/fidelity_plan.h"
#include "harness/sha256.h"
#include "net/net.h"

namespace tcsb {
namespace {

using json = nlohmann::json;

std::string fmt_number(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

/// A JSON value as it appears in error messages: short, one line, with its type when that is the problem.
std::string describe(const json& j) {
  std::string text;
  if (j.is_string()) text = "string " + j.dump();
  else if (j.is_object()) text = "an object";
  else if (j.is_array()) text = "an array";
  else text = j.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

std::string key_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}
std::string index_path(const std::string& parent, std::size_t i) { return parent + "[" + std::to_string(i) + "]"; }

/// A range of real numbers for messages and checks; infinite bounds print as ">= lo" / "> lo".
struct Interval {
  double lo;
  bool lo_open;
  double hi = std::numeric_limits<double>::infinity();
  bool hi_open = true;
  bool contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    if (std::isinf(lo) && std::isinf(hi)) return "a finite number";
    if (std::isinf(hi)) return "a finite number " + std::string(lo_open ? "> " : ">= ") + fmt_number(lo);
    return "a number in " + std::string(lo_open ? "(" : "[") + fmt_number(lo) + ", " + fmt_number(hi) +
           (hi_open ? ")" : "]");
  }
};

/// Typed access to a JSON document that throws SuiteError naming the file and the field.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw SuiteError(file_, field, problem);
  }

  long long integer(const json& j, const std::string& path, long long lo, long long hi) const {
    const std::string want = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got ";
    if (!j.is_number_integer()) fail(path, want + describe(j));
    if (j.is_number_unsigned() && j.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) fail(path, want + j.dump());
    const long long v = j.get<long long>();
    if (v < lo || v > hi) fail(path, want + j.dump());
    return v;
  }
  std::uint64_t unsigned_integer(const json& j, const std::string& path) const {
    if (!j.is_number_integer() || (!j.is_number_unsigned() && j.get<long long>() < 0)) {
      fail(path, "must be a non-negative integer, got " + describe(j));
    }
    return j.get<std::uint64_t>();
  }
  double number(const json& j, const std::string& path, const Interval& range) const {
    if (!j.is_number()) fail(path, "must be " + range.text() + ", got " + describe(j));
    const double v = j.get<double>();
    if (!range.contains(v)) fail(path, "must be " + range.text() + ", got " + j.dump());
    return v;
  }
  bool boolean(const json& j, const std::string& path) const {
    if (!j.is_boolean()) fail(path, "must be true or false, got " + describe(j));
    return j.get<bool>();
  }
  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, "must be a string, got " + describe(j));
    return j.get<std::string>();
  }
  const json& array(const json& j, const std::string& path, bool allow_empty = false) const {
    if (!j.is_array()) fail(path, "must be an array, got " + describe(j));
    if (!allow_empty && j.empty()) fail(path, "must not be empty");
    return j;
  }
  /// An array of exactly `n` numbers in `range`.
  template <std::size_t n>
  std::array<double, n> numbers(const json& j, const std::string& path, const Interval& range) const {
    if (!j.is_array() || j.size() != n) {
      fail(path, "must be an array of " + std::to_string(n) + " numbers, got " + describe(j));
    }
    std::array<double, n> out{};
    for (std::size_t i = 0; i < n; ++i) out[i] = number(j[i], index_path(path, i), range);
    return out;
  }
  /// One of `options` (an enum spelled as a string).
  template <class E>
  E choice(const json& j, const std::string& path,
           std::initializer_list<std::pair<std::string_view, E>> options) const {
    if (j.is_string()) {
      for (const auto& [name, value] : options) {
        if (j.get<std::string>() == name) return value;
      }
    }
    std::string list;
    for (const auto& option : options) list += (list.empty() ? "\"" : ", \"") + std::string(option.first) + "\"";
    fail(path, "must be one of " + list + ", got " + describe(j));
  }

 private:
  std::string file_;
};

/// One JSON object at `path`: rejects keys outside `allowed`, then reads members, building their paths for errors.
/// The read() overloads leave `out` alone when an optional key is absent, so the struct's default stands.
class Object {
 public:
  Object(const Reader& r, const json& j, std::string path, std::initializer_list<std::string_view> allowed)
      : r_(r), j_(j), path_(std::move(path)) {
    if (!j.is_object()) r.fail(path_, "must be an object, got " + describe(j));
    for (const auto& item : j.items()) {
      if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
      std::string list;
      for (const std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      r.fail(at(item.key()), "unknown key (expected one of: " + list + ")");
    }
  }
  std::string at(std::string_view key) const { return key_path(path_, key); }
  /// The member `key`, or nullptr; with `required`, a missing key is an error.
  const json* find(const char* key, bool required = false) const {
    const auto it = j_.find(key);
    if (it != j_.end()) return &*it;
    if (required) r_.fail(at(key), "required key is missing");
    return nullptr;
  }
  const json& need(const char* key) const { return *find(key, true); }

  void read(const char* key, int& out, long long lo, long long hi, bool required = false) const {
    if (const json* v = find(key, required)) out = static_cast<int>(r_.integer(*v, at(key), lo, hi));
  }
  void read(const char* key, double& out, const Interval& range, bool required = false) const {
    if (const json* v = find(key, required)) out = r_.number(*v, at(key), range);
  }
  void read(const char* key, bool& out) const {
    if (const json* v = find(key)) out = r_.boolean(*v, at(key));
  }
  template <class E>
  void read(const char* key, E& out, std::initializer_list<std::pair<std::string_view, E>> options) const {
    if (const json* v = find(key)) out = r_.choice(*v, at(key), options);
  }

 private:
  const Reader& r_;
  const json& j_;
  std::string path_;
};

/// Parses text, rejecting malformed JSON (with the parser's position) and duplicate keys (which nlohmann would
/// silently resolve to the last one — a suite stating "steps" twice is a mistake, not a choice).
json parse_json(const std::string& text, const Reader& r) {
  struct Frame {
    bool is_array = false;
    std::size_t index = 0;
    std::string key;
    std::set<std::string> seen;
  };
  std::vector<Frame> stack;
  auto path = [&stack] {
    std::string p;
    for (const Frame& f : stack) p = f.is_array ? index_path(p, f.index) : key_path(p, f.key);
    return p;
  };
  // A value just ended in the innermost container: in an array, the next element gets the next index.
  auto value_done = [&stack] {
    if (!stack.empty() && stack.back().is_array) ++stack.back().index;
  };
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: stack.push_back(Frame{}); break;
      case json::parse_event_t::array_start: stack.push_back(Frame{true, 0, {}, {}}); break;
      case json::parse_event_t::key: {
        Frame& f = stack.back();
        f.key = parsed.get<std::string>();
        if (!f.seen.insert(f.key).second) r.fail(path(), "duplicate key (each key may appear once)");
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack.pop_back();
        value_done();
        break;
      case json::parse_event_t::value: value_done(); break;
    }
    return true;
  };
  try {
    return json::parse(text, callback);
  } catch (const json::exception& e) {
    std::string message = e.what();
    if (const auto close = message.find("] "); message.rfind("[json.exception", 0) == 0 && close != std::string::npos) {
      message.erase(0, close + 2);
    }
    std::replace(message.begin(), message.end(), '\n', ' ');
    r.fail("", "malformed JSON: " + message);
  }
}

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr Interval kPositive{0.0, true}, kNonNegative{0.0, false}, kAnyFinite{-kInf, true};
constexpr Interval kFraction{0.0, true, 1.0, false};  // (0, 1]

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
    const std::array<double, 2> xz = r.numbers<2>(*size, o.at("size"), kPositive);
    net.size_x = xz[0];
    net.size_z = xz[1];
  }
  o.read("elevation", net.elevation, kAnyFinite);
  if (const json* mass = o.find("mass")) {
    const Object m(r, *mass, o.at("mass"), {"total", "per_node"});
    if (mass->size() != 1) {
      r.fail(o.at("mass"), "must have exactly one of \"total\" or \"per_node\", got " + mass->dump());
    }
    net.mass_mode = mass->contains("total") ? MassMode::kTotal : MassMode::kPerNode;
    m.read(net.mass_mode == MassMode::kTotal ? "total" : "per_node", net.mass, kPositive);
  }
  if (const json* pinned = o.find("pinned")) {
    const std::string p = o.at("pinned");
    if (pinned->is_array()) {
      net.pinned_corners = 0;
      for (std::size_t i = 0; i < pinned->size(); ++i) {
        const unsigned bit = r.choice<unsigned>((*pinned)[i], index_path(p, i),
                                                {{"min_min", kCornerMinMin}, {"max_min", kCornerMaxMin},
                                                 {"min_max", kCornerMinMax}, {"max_max", kCornerMaxMax}});
        if (net.pinned_corners & bit) r.fail(index_path(p, i), "duplicate corner " + (*pinned)[i].dump());
        net.pinned_corners |= bit;
      }
    } else if (pinned->is_string()) {
      net.pinned_corners = r.choice<unsigned>(*pinned, p, {{"corners", kAllCorners}, {"none", 0u}});
    } else {
      r.fail(p, "must be \"corners\", \"none\" or a list of corners, got " + describe(*pinned));
    }
  }
  o.read("shear", net.shear_links);
  o.read("bend", net.bend_links);
  return net;
}

void parse_settings(const Reader& r, const Object& root, Suite& s) {
  const Object solver(r, root.need("solver"), "solver",
                      {"piterations", "viterations", "diterations", "damping", "stiffness"});
  solver.read("piterations", s.solver.piterations, 1, 1000, true);
  solver.read("viterations", s.solver.viterations, 0, 1000);
  solver.read("diterations", s.solver.diterations, 0, 1000);
  solver.read("damping", s.solver.damping, Interval{0.0, false, 1.0, true});
  solver.read("stiffness", s.solver.linear_stiffness, kFraction);

  if (const json* j = root.find("tcsb")) {
    const Object tc(r, *j, "tcsb", {"blend_steps", "placement"});
    tc.read("blend_steps", s.tcsb.blend_steps, 1, 1000);
    tc.read("placement", s.tcsb.placement, {{"affine", Placement::kAffine}, {"rigid", Placement::kRigid}});
  }

  if (const json* j = root.find("feedback")) {
    const Object fb(r, *j, "feedback",
                    {"policy", "threshold", "max_ops_per_step", "evaluation_interval", "global_motion_scale",
                     "illumination", "light_direction", "parallel", "threads", "max_step_ms"});
    FeedbackSettings& f = s.feedback;
    fb.read("policy", f.policy, {{"saliency", PolicyKind::kSaliency}, {"random", PolicyKind::kRandom}});
    fb.read("threshold", f.threshold, kNonNegative);
    fb.read("max_ops_per_step", f.max_ops_per_step, 1, 100000);
    fb.read("evaluation_interval", f.evaluation_interval, 1, 1000);
    fb.read("global_motion_scale", f.global_motion_scale, kPositive);
    fb.read("illumination", f.illumination);
    if (const json* light = fb.find("light_direction")) {
      f.light_direction = r.numbers<3>(*light, fb.at("light_direction"), kAnyFinite);
      if (f.light_direction == std::array<double, 3>{}) r.fail(fb.at("light_direction"), "must not be the zero vector");
    }
    fb.read("parallel", f.parallel);
    fb.read("threads", f.threads, 1, 64);
    fb.read("max_step_ms", f.max_step_ms, kNonNegative);
  }

  if (const json* j = root.find("fidelity")) {
    const Object fi(r, *j, "fidelity", {"enabled", "rms_threshold_pct", "pareto_targets", "ablations"});
    fi.read("enabled", s.fidelity.enabled);
    fi.read("rms_threshold_pct", s.fidelity.rms_threshold_pct, kPositive);
    if (const json* targets = fi.find("pareto_targets")) {
      r.array(*targets, fi.at("pareto_targets"), true);
      for (std::size_t i = 0; i < targets->size(); ++i) {
        s.fidelity.pareto_targets.push_back(r.number((*targets)[i], index_path(fi.at("pareto_targets"), i), kFraction));
      }
    }
    fi.read("ablations", s.fidelity.ablations);
  }
}

std::optional<std::uint64_t> mem_available_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    unsigned long long kib = 0;
    if (std::sscanf(line.c_str(), "MemAvailable: %llu kB", &kib) == 1) return static_cast<std::uint64_t>(kib) * 1024;
  }
  return std::nullopt;
}

std::string fmt_bytes(double bytes) {
  char buf[48];
  if (bytes >= 1024.0 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  else std::snprintf(buf, sizeof buf, "%.1f MiB", bytes / (1024.0 * 1024));
  return buf;
}

// Per-element memory, deliberately on the high side (sizes measured with sizeof on Bullet 3.24, single precision):
//  - a Bullet node: btSoftBody::Node 256 B + its DBVT leaf and share of inner nodes ~ 2 x 64 B (btDbvtNode is 56 B,
//    rounded up for the allocator);
//  - a Bullet link: btSoftBody::Link 72 B;
//  - a Bullet face (CreatePatch makes 2 per cell, bullet_patch only): btSoftBody::Face 144 B + ~ 2 x 64 B of tree;
//  - our Net: ~ 48 B per node (rest position, mass, pin flag, padding) + 12 B per link (NetLink);
//  - the LOD tree: ~ 4/3 N tree nodes x 112 B;
//  - a TC-SB body: Bullet nodes reserved for all 4/3 N tree nodes, ~ 200 B of bookkeeping per tree node (cut
//    membership, incidence lists, feedback state), and Bullet links for up to 3 L;
//  - the recorder: ~ 32 B per step sample, for every step (warm-up included) of every run of the suite.
constexpr double kBulletNodeBytes = 256 + 2 * 64;
constexpr double kBulletLinkBytes = 72;
constexpr double kBulletFaceBytes = 144 + 2 * 64;
constexpr double kNetNodeBytes = 48, kNetLinkBytes = 12;
constexpr double kTreeNodeBytes = 112, kTreeNodesPerLeaf = 4.0 / 3.0;
constexpr double kTcBookkeepingBytes = 200, kTcLinkFactor = 3;
constexpr double kSampleBytes = 32;

/// Peak bytes while cases of net `spec` run: the shared net, one body per method; or, in the fidelity pass, which
/// runs afterwards, the reference and every subject at once (each counted as a TC-SB body, the largest kind).
double net_peak_bytes(const Suite& suite, const NetSpec& spec) {
  const double n = static_cast<double>(spec.node_count());
  const double l = static_cast<double>(expected_link_count(spec));
  const double tree = kTreeNodesPerLeaf * n;
  const double plain = n * kBulletNodeBytes + l * kBulletLinkBytes;
  const double tcsb_body = tree * (kBulletNodeBytes + kTcBookkeepingBytes) + kTcLinkFactor * l * kBulletLinkBytes;
  const double shared = n * kNetNodeBytes + l * kNetLinkBytes + tree * kTreeNodeBytes;
  double bytes = shared;
  bool has_tcsb = false;
  for (const Method m : suite.methods) {
    switch (m) {
      case Method::kPlain: bytes += plain; break;
      case Method::kBulletPatch:
        bytes += plain + 2.0 * (spec.width - 1) * (spec.height - 1) * kBulletFaceBytes;
        break;
      case Method::kTcsb:
        has_tcsb = true;
        bytes += tcsb_body;
        break;
    }
  }
  const double subjects = has_tcsb ? static_cast<double>(fidelity_plan(suite).size()) : 0.0;
  const double fidelity = shared + plain + subjects * tcsb_body;
  return subjects > 0 ? std::max(bytes, fidelity) : bytes;
}

double recorder_bytes(const Suite& suite) {
  const double runs = static_cast<double>(expand_cases(suite).size()) * suite.repetitions;
  return runs * (static_cast<double>(suite.steps) + suite.warmup_steps) * kSampleBytes;
}

std::size_t peak_net_index(const Suite& suite) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < suite.nets.size(); ++i) {
    if (net_peak_bytes(suite, suite.nets[i]) > net_peak_bytes(suite, suite.nets[best])) best = i;
  }
  return best;
}

void check_memory(const Suite& suite, const Reader& r) {
  const std::optional<std::uint64_t> available = mem_available_bytes();
  if (!available || suite.nets.empty()) return;
  const double needed = static_cast<double>(estimate_peak_bytes(suite));
  const double usable = 0.8 * static_cast<double>(*available);
  if (needed <= usable) return;
  const std::size_t i = peak_net_index(suite);
  const NetSpec& net = suite.nets[i];
  const std::string size = std::to_string(net.width) + " x " + std::to_string(net.height) + " = " +
                           std::to_string(net.node_count()) + " nodes";
  r.fail(index_path("nets", i), "net \"" + net.name + "\" (" + size + ") needs about " + fmt_bytes(needed) +
                                    " with all methods' bodies alive, but only " + fmt_bytes(usable) +
                                    " may be used (80% of MemAvailable " + fmt_bytes(static_cast<double>(*available)) +
                                    ")");
}

}  // namespace

const char* method_name(Method method) {
  switch (method) {
    case Method::kPlain: return "plain";
    case Method::kBulletPatch: return "bullet_patch";
    case Method::kTcsb: return "tcsb";
  }
  return "unknown";
}

std::uint64_t estimate_peak_bytes(const Suite& suite) {
  double peak = 0;
  for (const NetSpec& net : suite.nets) peak = std::max(peak, net_peak_bytes(suite, net));
  const double bytes = std::ceil(peak + recorder_bytes(suite));
  constexpr double kMax = 1.8e19;  // just under 2^64: saturate rather than overflow
  return bytes >= kMax ? std::numeric_limits<std::uint64_t>::max() : static_cast<std::uint64_t>(bytes);
}

Suite parse_suite_text(const std::string& text, const std::string& file) {
  const Reader r(file);
  const json doc = parse_json(text, r);
  if (!doc.is_object()) r.fail("", "the suite must be a JSON object, got " + describe(doc));
  const Object root(r, doc, "", {"name", "description", "nets", "methods", "compression", "dt", "gravity", "steps",
                                 "warmup_steps", "repetitions", "seed", "solver", "tcsb", "feedback", "fidelity"});
  Suite s;
  s.path = file;
  s.sha256 = sha256_hex(text);
  s.name = r.string(root.need("name"), "name");
  if (s.name.empty()) r.fail("name", "must not be empty");
  if (const json* d = root.find("description")) s.description = r.string(*d, "description");

  const json& nets = r.array(root.need("nets"), "nets");
  for (std::size_t i = 0; i < nets.size(); ++i) {
    s.nets.push_back(parse_net(r, nets[i], index_path("nets", i)));
    for (std::size_t k = 0; k < i; ++k) {
      if (s.nets[k].name != s.nets[i].name) continue;
      r.fail(index_path("nets", i) + ".name", "duplicate net name \"" + s.nets[i].name + "\" (also nets[" +
                                                  std::to_string(k) + "])");
    }
  }

  const json& methods = r.array(root.need("methods"), "methods");
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const Method m = r.choice<Method>(methods[i], index_path("methods", i),
        {{"plain", Method::kPlain}, {"bullet_patch", Method::kBulletPatch}, {"tcsb", Method::kTcsb}});
    if (std::find(s.methods.begin(), s.methods.end(), m) != s.methods.end()) {
      r.fail(index_path("methods", i), "duplicate method \"" + std::string(method_name(m)) + "\"");
    }
    s.methods.push_back(m);
  }
  const bool has_tcsb = std::find(s.methods.begin(), s.methods.end(), Method::kTcsb) != s.methods.end();
  if (const json* compression = root.find("compression", has_tcsb)) {
    if (!has_tcsb) r.fail("compression", "only allowed when methods contains \"tcsb\"");
    r.array(*compression, "compression");
    for (std::size_t i = 0; i < compression->size(); ++i) {
      const double c = r.number((*compression)[i], index_path("compression", i), kFraction);
      if (std::find(s.compression.begin(), s.compression.end(), c) != s.compression.end()) {
        r.fail(index_path("compression", i), "duplicate compression target " + fmt_number(c));
      }
      s.compression.push_back(c);
    }
  }

  root.read("dt", s.world.dt, kFraction, true);
  root.read("gravity", s.world.gravity, kNonNegative);
  root.read("steps", s.steps, 1, INT_MAX, true);
  root.read("warmup_steps", s.warmup_steps, 0, INT_MAX, true);
  root.read("repetitions", s.repetitions, 1, kMaxRepetitions, true);
  s.seed = r.unsigned_integer(root.need("seed"), "seed");
  parse_settings(r, root, s);

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
  // The fidelity pass compares TC-SB (and the ablations at TC-SB's targets) with the reference: without TC-SB there
  // is nothing to measure, and silently measuring nothing would look like a pass.
  if (s.fidelity.enabled && !has_tcsb) r.fail("fidelity.enabled", "requires methods to contain \"tcsb\"");
  check_memory(s, r);
  return s;
}

Suite parse_suite(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw SuiteError(file, "", std::filesystem::exists(path, ec) ? "cannot read: not a regular file"
                                                                 : "cannot read: no such file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) throw SuiteError(file, "", "cannot read: cannot open (permissions?)");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw SuiteError(file, "", "cannot read: I/O error");
  Suite suite = parse_suite_text(text, file);
  suite.path = path;
  return suite;
}

}  // namespace tcsb
