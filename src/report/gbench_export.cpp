#include "report/gbench_export.h"

#include <cmath>
#include <optional>
#include <string_view>

#include "report/json_report.h"

namespace tcsb {
namespace {

using ojson = nlohmann::ordered_json;

// Times are written in microseconds although tcsb measures milliseconds: compare.py prints times with no decimals,
// so sub-millisecond steps would all read "0" in ms.
constexpr double kMicrosecondsPerMs = 1000.0;

/// A context field, or `fallback` when a (hand-made) file lacks it or has another type.
template <class T>
T member_or(const ojson& object, const char* key, T fallback) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  try {
    return it->get<T>();
  } catch (const nlohmann::json::exception&) {
    return fallback;
  }
}

ojson context_json(const ResultView& r) {
  const ojson& c = r.context;
  ojson caches = ojson::array();
  if (const auto it = c.find("caches"); it != c.end() && it->is_array()) {
    for (const ojson& cache : *it) {
      caches.push_back({{"type", member_or<std::string>(cache, "type", "")},
                        {"level", member_or<int>(cache, "level", 0)},
                        {"size", member_or<std::int64_t>(cache, "size_bytes", 0)},
                        {"num_sharing", member_or<int>(cache, "num_sharing", 0)}});
    }
  }
  const std::string governor = member_or<std::string>(c, "cpu_governor", "");
  // Google Benchmark's keys first (its tools read them by name), then tcsb's own as custom context, as
  // --benchmark_context=key=value would add them.
  return {
      {"date", member_or<std::string>(c, "date_utc", "")},
      {"host_name", member_or<std::string>(c, "host", "")},
      {"executable", "tcsb"},
      {"num_cpus", member_or<int>(c, "cores", 0)},
      {"mhz_per_cpu", static_cast<std::int64_t>(std::llround(member_or<double>(c, "mhz", 0.0)))},
      {"cpu_scaling_enabled", !governor.empty() && governor != "performance"},
      {"caches", std::move(caches)},
      // tcsb records only the 1-minute load average.
      {"load_avg", ojson::array({json_number(member_or<double>(c, "load_average_1m", 0.0))})},
      {"library_build_type", member_or<bool>(c, "optimized", false) ? "release" : "debug"},
      {"tcsb_suite", member_or<std::string>(r.suite, "name", "")},
      {"tcsb_suite_sha256", member_or<std::string>(r.suite, "sha256", "")},
      {"tcsb_git_commit", member_or<std::string>(c, "git_commit", "")},
      {"tcsb_cpu_model", member_or<std::string>(c, "cpu_model", "")},
      {"tcsb_build_type", member_or<std::string>(c, "build_type", "")},
      {"tcsb_bullet_version", member_or<std::string>(c, "bullet_version", "")},
  };
}

/// The fields every entry of one case shares, in Google Benchmark's order.
ojson entry_head(const std::string& name, const CaseView& c, std::size_t family, const char* run_type,
                 int repetitions) {
  return {{"name", name},        {"family_index", family}, {"per_family_instance_index", 0},
          {"run_name", c.label}, {"run_type", run_type},   {"repetitions", repetitions}};
}

void add_case(const ResultView& r, std::size_t family, ojson& out) {
  const CaseView& c = r.cases[family];
  for (const RepetitionView& rep : c.repetitions) {
    if (rep.status != "ok" || !rep.mean_step_ms) continue;
    ojson e = entry_head(c.label, c, family, "iteration", r.repetitions);
    e["repetition_index"] = rep.repetition;
    e["threads"] = 1;
    e["iterations"] = r.steps;
    e["real_time"] = json_number(kMicrosecondsPerMs * *rep.mean_step_ms);
    e["cpu_time"] = json_number(kMicrosecondsPerMs * *rep.mean_step_ms);
    e["time_unit"] = "us";
    e["N"] = json_number(rep.mean_nodes);
    e["L"] = json_number(rep.mean_links);
    e["I"] = json_number(rep.mean_interpolations);
    out.push_back(std::move(e));
  }
  // As Google Benchmark: aggregates only over repetitions. They are the run's own summary of the case (step_ms), not
  // the export's, so every format shows the same numbers; the counters are the case's means, so they go with the
  // mean alone (the run summarises N, L and I by their means only).
  if (c.step_ms_count < 2) return;
  struct Aggregate {
    const char* name;
    const char* unit;
    std::optional<double> value;
  };
  // The cv is a fraction, not a time: it is not converted.
  const Aggregate aggregates[] = {
      {"mean", "time", c.mean_step_ms},
      {"median", "time", c.median_step_ms},
      {"stddev", "time", c.stddev_step_ms},
      {"cv", "percentage", c.cv_step_ms},
  };
  for (const Aggregate& a : aggregates) {
    if (!a.value) continue;
    ojson e = entry_head(c.label + "_" + a.name, c, family, "aggregate", r.repetitions);
    e["threads"] = 1;
    e["aggregate_name"] = a.name;
    e["aggregate_unit"] = a.unit;
    e["iterations"] = c.step_ms_count;
    const double scale = std::string_view(a.unit) == "time" ? kMicrosecondsPerMs : 1.0;
    e["real_time"] = json_number(scale * *a.value);
    e["cpu_time"] = json_number(scale * *a.value);
    e["time_unit"] = "us";
    if (std::string_view(a.name) == "mean") {
      e["N"] = json_number(c.mean_nodes);
      e["L"] = json_number(c.mean_links);
      e["I"] = json_number(c.mean_interpolations);
    }
    out.push_back(std::move(e));
  }
}

}  // namespace

ojson gbench_json(const ResultView& result) {
  ojson benchmarks = ojson::array();
  for (std::size_t i = 0; i < result.cases.size(); ++i) add_case(result, i, benchmarks);
  ojson doc;
  doc["context"] = context_json(result);
  doc["benchmarks"] = std::move(benchmarks);
  return doc;
}

std::string GbenchFormat::render_native(const nlohmann::ordered_json& native) const {
  return json_text(gbench_json(read_result(native, "result")));
}

}  // namespace tcsb
