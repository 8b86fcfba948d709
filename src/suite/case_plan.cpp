// Case expansion and interleaved run order.
#include "suite/case_plan.h"

#include <charconv>
#include <string_view>

namespace tcsb {

std::vector<CaseKey> expand_cases(const Suite& suite) {
  std::vector<CaseKey> cases;
  for (std::size_t configuration = 0; configuration < configuration_count(suite); ++configuration) {
    for (std::size_t net = 0; net < suite.nets.size(); ++net) {
      for (const Method method : suite.methods) {
        if (method == Method::kTcsb) {
          for (const double target : suite.compression) cases.push_back({net, method, target, configuration});
        } else if (method == Method::kPlainEqual) {
          for (const double target : suite.compression)
            if (target < 1.0) cases.push_back({net, method, target, configuration});
        } else {
          cases.push_back({net, method, std::nullopt, configuration});
        }
      }
    }
  }
  return cases;
}

std::uint64_t case_count(const Suite& suite) {
  std::uint64_t per_net = 0;
  for (const Method method : suite.methods) {
    if (method == Method::kTcsb) {
      per_net += suite.compression.size();
    } else if (method == Method::kPlainEqual) {
      for (const double target : suite.compression) per_net += target < 1.0;
    } else {
      ++per_net;
    }
  }
  // Each factor is bounded by what a 16 MiB file can list: the product of three fits 64 bits.
  return static_cast<std::uint64_t>(configuration_count(suite)) * suite.nets.size() * per_net;
}

std::size_t cases_per_configuration(const Suite& suite) {
  Suite one = suite;  // the cases of one configuration: the same for each
  one.configurations.clear();
  return expand_cases(one).size();
}

std::size_t index_in_configuration(std::size_t per_configuration, std::size_t case_index) {
  return per_configuration == 0 ? case_index : case_index % per_configuration;
}

std::size_t index_in_configuration(const Suite& suite, std::size_t case_index) {
  return index_in_configuration(cases_per_configuration(suite), case_index);
}

std::vector<PlannedRun> interleaved_plan(const Suite& suite, const std::vector<CaseKey>& cases) {
  const std::size_t nets = suite.nets.size();
  std::vector<PlannedRun> plan;
  plan.reserve(cases.size() * static_cast<std::size_t>(suite.repetitions > 0 ? suite.repetitions : 0));
  // The machine's speed drifts over seconds, so every net is measured in every repetition (rather than one net's
  // repetitions back to back): each net's median then sees the same mix of fast and slow moments, and the
  // cross-net fits (step time and operation cost against node count) compare like with like. The net that starts
  // a repetition rotates, so no net is always first or last.
  const auto first_case_of = [&](std::size_t net) {
    std::size_t c = 0;
    while (c < cases.size() && cases[c].net != net) ++c;
    return c;  // cases.size() when the net has none
  };
  std::size_t first_net = 0;
  for (int rep = 0; rep < suite.repetitions && nets > 0; ++rep) {
    if (rep > 0) {
      // Never the same case twice in a row (the second run would find the first's data in the caches). Rotating
      // would do that only with two nets of one case each; then the order stays.
      const std::size_t next = (first_net + 1) % nets;
      if (plan.empty() || first_case_of(next) != plan.back().case_index) first_net = next;
    }
    for (std::size_t k = 0; k < nets; ++k) {
      const std::size_t net = (first_net + k) % nets;
      for (std::size_t c = 0; c < cases.size(); ++c) {
        if (cases[c].net == net) plan.push_back({c, rep});
      }
    }
  }
  return plan;
}

std::string case_label(const Suite& suite, const CaseKey& key) {
  std::string label = key.net < suite.nets.size() ? suite.nets[key.net].name : std::to_string(key.net);
  label += '/';
  label += method_name(key.method);
  if (key.compression) {
    // Shortest round-trip form, with ".0" kept on whole numbers so "tcsb@1.0" reads as a fraction.
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, *key.compression);
    std::string_view number(buf, ec == std::errc() ? static_cast<std::size_t>(end - buf) : 0);
    label += '@';
    label += number;
    if (number.find_first_of(".en") == std::string_view::npos) label += ".0";
  }
  if (key.configuration < suite.configurations.size())
    label += "[" + suite.configurations[key.configuration].label + "]";
  return label;
}

std::uint64_t case_seed(const Suite& suite, std::size_t case_index) { return suite.seed * 1000003ULL + case_index; }

}  // namespace tcsb
