#include "suite/suite_settings_table.h"

#include <array>
#include <climits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace tcsb {
namespace {

using namespace suite_fields;

const Suite& default_settings_suite() {
  static const Suite defaults;
  return defaults;
}

/// The member a chain of pointers to members reaches from `object`: &Suite::feedback, &FeedbackSettings::view.
template <auto First, auto... Rest, class Object>
auto& member_at(Object& object) {
  if constexpr (sizeof...(Rest) == 0)
    return object.*First;
  else
    return member_at<Rest...>(object.*First);
}

template <class T>
constexpr SettingType setting_type() {
  if constexpr (std::is_same_v<T, bool>)
    return SettingType::kBoolean;
  else if constexpr (std::is_same_v<T, int>)
    return SettingType::kInteger;
  else if constexpr (std::is_same_v<T, std::uint64_t>)
    return SettingType::kUnsigned;
  else if constexpr (std::is_same_v<T, double>)
    return SettingType::kNumber;
  else if constexpr (std::is_enum_v<T>)
    return SettingType::kChoice;
  else {
    static_assert(std::is_same_v<T, std::array<double, 3>>, "a suite setting is a scalar, a choice or a direction");
    return SettingType::kDirection;
  }
}

template <class T>
T read_setting_value(const SettingRange& range, const Reader& r, const json& v, const std::string& at) {
  if constexpr (std::is_same_v<T, bool>)
    return r.boolean(v, at);
  else if constexpr (std::is_same_v<T, int>)
    return static_cast<int>(r.integer(v, at, range.lo, range.hi));
  else if constexpr (std::is_same_v<T, std::uint64_t>)
    return r.unsigned_integer(v, at);
  else if constexpr (std::is_same_v<T, double>)
    return r.number(v, at, range.numbers);
  else if constexpr (std::is_enum_v<T>)
    return static_cast<T>(r.choice(v, at, range.choices));
  else {
    const T direction = r.numbers<3>(v, at, range.numbers);
    if (direction == T{}) r.fail(at, "must not be the zero vector");
    return direction;
  }
}

template <class T>
nlohmann::ordered_json setting_json(const SettingRange& range, const T& value) {
  if constexpr (std::is_enum_v<T>) {
    for (const auto& [name, option] : range.choices)
      if (option == static_cast<int>(value)) return std::string(name);
    throw std::logic_error("a choice of the suite settings table lacks the enumerator " +
                           std::to_string(static_cast<int>(value)));
  } else {
    return value;
  }
}

/// The member at Path, as a row's SettingMember.
template <auto... Path>
constexpr SettingMember setting_member() {
  using T = std::remove_cvref_t<decltype(member_at<Path...>(std::declval<Suite&>()))>;
  return {setting_type<T>(),
          [](const SuiteSetting& row, const Reader& r, const json& v, const std::string& at, Suite& s) {
            member_at<Path...>(s) = read_setting_value<T>(row.range, r, v, at);
          },
          [](const SuiteSetting& row, const Suite& s) { return setting_json(row.range, member_at<Path...>(s)); },
          [](const Suite& s) { return member_at<Path...>(s) == member_at<Path...>(default_settings_suite()); }};
}

/// A flag's, or the seed's (any unsigned 64-bit integer): nothing to bound.
constexpr SettingRange kUnbounded{};
constexpr SettingRange integer_range(long long lo, long long hi) { return {lo, hi, {0.0, false}, {}}; }
constexpr SettingRange number_range(NumberRange range) { return {0, 0, range, {}}; }
constexpr SettingRange choice_range(std::span<const SettingChoice> choices) { return {0, 0, {0.0, false}, choices}; }

constexpr SettingChoice kPlacements[] = {{"affine", static_cast<int>(Placement::kAffine)},
                                         {"rigid", static_cast<int>(Placement::kRigid)}};
constexpr SettingChoice kInterfaces[] = {{"links", static_cast<int>(Interfaces::kLinks)},
                                         {"hanging", static_cast<int>(Interfaces::kHanging)}};
constexpr SettingChoice kMasses[] = {{"blocks", static_cast<int>(Masses::kBlocks)},
                                     {"cut", static_cast<int>(Masses::kCut)}};
constexpr SettingChoice kPolicies[] = {{"saliency", static_cast<int>(PolicyKind::kSaliency)},
                                       {"random", static_cast<int>(PolicyKind::kRandom)}};
constexpr SettingChoice kBudgetScopes[] = {{"body", static_cast<int>(BudgetScope::kBody)},
                                           {"world", static_cast<int>(BudgetScope::kWorld)}};

/// The step the compliant material's constants are made for is the suite's step.
void step_dt_follows_dt(Suite& s) { s.solver.step_dt = s.world.dt; }

/// Masses that follow the cut need blocks resting on their first leaf.
void cut_masses_rest_on_vertices(Suite& s) {
  if (s.tcsb.masses == Masses::kCut)
    for (NetSpec& net : s.nets) net.lod_rest = RestPlacement::kVertex;
}

// In the order the result's suite block has always listed them (root, solver, tcsb, feedback; the always-written
// before the others). An axis row's number is its place in configuration labels, which results written before the
// table fixed; a new axis takes the next number. Axes are the scalar settings of how one case simulates, so
// configurations of one suite run the same cases and their ratios, tables and fits compare. Not the masses (the mass
// model decides where the tree's blocks rest, and every case of a net shares its tree), what the machine gives a case
// (parallel, threads, max_step_ms) or how cases are measured (repetitions, interleaving).
// Columns: path, member, range, axis (kNoAxis or its label place), required, written (kAlways), then.
constexpr SuiteSetting kSettings[] = {
    {"steps", setting_member<&Suite::steps>(), integer_range(1, INT_MAX), 32, true},
    {"warmup_steps", setting_member<&Suite::warmup_steps>(), integer_range(0, INT_MAX), 33, true},
    {"repetitions", setting_member<&Suite::repetitions>(), integer_range(1, kMaxRepetitions), kNoAxis, true},
    {"interleave_steps", setting_member<&Suite::interleave_steps>(), integer_range(0, INT_MAX)},
    {"interleave_across_nets", setting_member<&Suite::interleave_across_nets>(), kUnbounded},
    {"dt", setting_member<&Suite::world, &WorldSettings::dt>(), number_range(kFraction), 30, true, Written::kAlways,
     step_dt_follows_dt},
    {"gravity", setting_member<&Suite::world, &WorldSettings::gravity>(), number_range(kSceneNonNegative), 31},
    {"seed", setting_member<&Suite::seed>(), kUnbounded, 29, true, Written::kNever},
    {"solver.piterations", setting_member<&Suite::solver, &SolverSettings::piterations>(), integer_range(1, 1000), 1,
     true},
    {"solver.viterations", setting_member<&Suite::solver, &SolverSettings::viterations>(), integer_range(0, 1000), 2},
    {"solver.diterations", setting_member<&Suite::solver, &SolverSettings::diterations>(), integer_range(0, 1000), 3},
    {"solver.damping", setting_member<&Suite::solver, &SolverSettings::damping>(),
     number_range({0.0, false, 1.0, true}), 4},
    {"solver.stiffness", setting_member<&Suite::solver, &SolverSettings::linear_stiffness>(), number_range(kFraction),
     5},
    {"tcsb.blend_steps", setting_member<&Suite::tcsb, &TcSettings::blend_steps>(), integer_range(1, 1000), 6},
    {"tcsb.placement", setting_member<&Suite::tcsb, &TcSettings::placement>(), choice_range(kPlacements), 8},
    {"tcsb.restore_order", setting_member<&Suite::tcsb, &TcSettings::restore_order>(), kUnbounded, 10},
    {"tcsb.restore_order_min_nodes", setting_member<&Suite::tcsb, &TcSettings::restore_order_min_nodes>(),
     integer_range(0, INT_MAX), 12},
    {"tcsb.rebuild_dbvt", setting_member<&Suite::tcsb, &TcSettings::rebuild_dbvt>(), kUnbounded, 13, false,
     Written::kUnlessDefault},
    {"tcsb.interfaces", setting_member<&Suite::tcsb, &TcSettings::interfaces>(), choice_range(kInterfaces), 9, false,
     Written::kUnlessDefault},
    {"tcsb.masses", setting_member<&Suite::tcsb, &TcSettings::masses>(), choice_range(kMasses), kNoAxis, false,
     Written::kUnlessDefault, cut_masses_rest_on_vertices},
    {"tcsb.exact_order", setting_member<&Suite::tcsb, &TcSettings::exact_order>(), kUnbounded, 11, false,
     Written::kUnlessDefault},
    {"tcsb.arrivals_collide", setting_member<&Suite::tcsb, &TcSettings::arrivals_collide>(), kUnbounded, 14, false,
     Written::kUnlessDefault},
    {"tcsb.start_level", setting_member<&Suite::tcsb, &TcSettings::start_level>(), integer_range(0, 30), 7, false,
     Written::kUnlessDefault},
    {"feedback.policy", setting_member<&Suite::feedback, &FeedbackSettings::policy>(), choice_range(kPolicies), 15},
    {"feedback.threshold", setting_member<&Suite::feedback, &FeedbackSettings::threshold>(), number_range(kNonNegative),
     16},
    {"feedback.max_ops_per_step", setting_member<&Suite::feedback, &FeedbackSettings::max_ops_per_step>(),
     integer_range(1, 100000), 17},
    {"feedback.evaluation_interval", setting_member<&Suite::feedback, &FeedbackSettings::evaluation_interval>(),
     integer_range(1, 1000), 18},
    {"feedback.global_motion_scale", setting_member<&Suite::feedback, &FeedbackSettings::global_motion_scale>(),
     number_range(kPositive), 19},
    {"feedback.illumination", setting_member<&Suite::feedback, &FeedbackSettings::illumination>(), kUnbounded, 20},
    {"feedback.light_direction", setting_member<&Suite::feedback, &FeedbackSettings::light_direction>(),
     number_range(kSceneCoordinate)},
    {"feedback.parallel", setting_member<&Suite::feedback, &FeedbackSettings::parallel>(), kUnbounded},
    {"feedback.threads", setting_member<&Suite::feedback, &FeedbackSettings::threads>(), integer_range(1, 64)},
    {"feedback.max_step_ms", setting_member<&Suite::feedback, &FeedbackSettings::max_step_ms>(),
     number_range(kNonNegative)},
    {"feedback.popping_charge", setting_member<&Suite::feedback, &FeedbackSettings::popping_charge>(),
     number_range(kNonNegative), 21, false, Written::kUnlessDefault},
    {"feedback.interface_charge", setting_member<&Suite::feedback, &FeedbackSettings::interface_charge>(),
     number_range(kNonNegative), 22, false, Written::kUnlessDefault},
    {"feedback.interface_tension", setting_member<&Suite::feedback, &FeedbackSettings::interface_tension>(),
     number_range(kNonNegative), 23, false, Written::kUnlessDefault},
    {"feedback.pin_level_pull", setting_member<&Suite::feedback, &FeedbackSettings::pin_level_pull>(),
     number_range(kNonNegative), 24, false, Written::kUnlessDefault},
    {"feedback.contact_saliency", setting_member<&Suite::feedback, &FeedbackSettings::contact_saliency>(),
     number_range(kUnit), 34, false, Written::kUnlessDefault},
    {"feedback.view", setting_member<&Suite::feedback, &FeedbackSettings::view>(), kUnbounded, 25, false,
     Written::kUnlessDefault},
    {"feedback.view_motion_scale", setting_member<&Suite::feedback, &FeedbackSettings::view_motion_scale>(),
     number_range(kPositive), 26, false, Written::kWithView},
    {"feedback.view_detail_px", setting_member<&Suite::feedback, &FeedbackSettings::view_detail_px>(),
     number_range(kPositive), 27, false, Written::kWithView},
    {"feedback.view_static_share", setting_member<&Suite::feedback, &FeedbackSettings::view_static_share>(),
     number_range(kUnit), 28, false, Written::kWithView},
    {"feedback.view_offscreen_share", setting_member<&Suite::feedback, &FeedbackSettings::view_offscreen_share>(),
     number_range(kUnit), kNoAxis, false, Written::kUnlessDefault},
    {"feedback.view_lookahead_s", setting_member<&Suite::feedback, &FeedbackSettings::view_lookahead_s>(),
     number_range(kNonNegative), kNoAxis, false, Written::kUnlessDefault},
    {"feedback.view_popping_charge", setting_member<&Suite::feedback, &FeedbackSettings::view_popping_charge>(),
     number_range(kNonNegative), kNoAxis, false, Written::kUnlessDefault},
    {"feedback.budget_scope", setting_member<&Suite::feedback, &FeedbackSettings::budget_scope>(),
     choice_range(kBudgetScopes), kNoAxis, false, Written::kUnlessDefault},
};

}  // namespace

std::string_view SuiteSetting::section() const {
  const std::size_t dot = path.find('.');
  return dot == std::string_view::npos ? std::string_view() : path.substr(0, dot);
}

std::string_view SuiteSetting::key() const { return path.substr(path.find('.') + 1); }

std::span<const SuiteSetting> suite_settings() { return kSettings; }

const SuiteSetting* find_suite_setting(std::string_view path) {
  for (const SuiteSetting& row : kSettings)
    if (row.path == path) return &row;
  return nullptr;
}

std::vector<std::string_view> suite_setting_keys(std::string_view section) {
  std::vector<std::string_view> keys;
  for (const SuiteSetting& row : kSettings)
    if (row.section() == section) keys.push_back(row.key());
  return keys;
}

void read_suite_setting(const SuiteSetting& row, const Reader& r, const json& value, const std::string& at,
                        Suite& suite) {
  row.member.read(row, r, value, at, suite);
  if (row.then) row.then(suite);
}

void read_suite_settings(const Reader& r, const Object& object, std::string_view section, Suite& suite) {
  for (const SuiteSetting& row : kSettings) {
    if (row.section() != section) continue;
    const std::string key(row.key());
    if (const json* v = object.find(key.c_str(), row.required)) read_suite_setting(row, r, *v, object.at(key), suite);
  }
}

bool suite_setting_written(const SuiteSetting& row, const Suite& suite) {
  switch (row.written) {
    case Written::kAlways: return true;
    case Written::kUnlessDefault: return !row.member.is_default(suite);
    case Written::kWithView: return suite.feedback.view;
    case Written::kNever: return false;
  }
  return false;
}

}  // namespace tcsb
