// Hand-built RunResults for the report and paper tests: no Bullet, every number chosen so the expected tables are
// obvious.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "run/run_result.h"
#include "suite/case_plan.h"

namespace tcsb::testing {

/// A suite with nets "n0", "n1", ... (no file behind it).
inline Suite synthetic_suite(int nets) {
  Suite s;
  s.name = "synthetic";
  s.path = "synthetic.json";
  s.sha256 = std::string(64, 'a');
  s.seed = 7;
  for (int i = 0; i < nets; ++i) {
    NetSpec n;
    n.name = std::string("n").append(std::to_string(i));  // not "n" + ...: GCC 12 -Wrestrict false positive
    s.nets.push_back(n);
  }
  s.methods = {Method::kPlain, Method::kTcsb};
  return s;
}

/// An ok repetition with the given mean step time.
inline RepetitionResult ok_repetition(int index, double mean_step_ms) {
  RepetitionResult r;
  r.repetition = index;
  r.mean_step_ms = r.median_step_ms = mean_step_ms;
  r.final_state_hash = std::string("h").append(std::to_string(index));
  return r;
}

/// An ok case whose summary says `median_ms`; one repetition per entry of `rep_ms` (default: one at median_ms).
inline CaseResult make_case(const Suite& suite, std::size_t net, Method method, std::optional<double> compression,
                            double nodes, double links, double interpolations, double median_ms,
                            std::vector<double> rep_ms = {}) {
  CaseResult c;
  c.key = CaseKey{net, method, compression};
  c.label = case_label(suite, c.key);
  c.net_name = suite.nets.at(net).name;
  c.mean_nodes = nodes;
  c.mean_links = links;
  c.mean_interpolations = interpolations;
  if (rep_ms.empty()) rep_ms = {median_ms};
  for (std::size_t r = 0; r < rep_ms.size(); ++r) {
    c.repetitions.push_back(ok_repetition(static_cast<int>(r), rep_ms[r]));
  }
  c.step_ms.count = rep_ms.size();
  c.step_ms.median = c.step_ms.mean = c.step_ms.min = c.step_ms.max = median_ms;
  return c;
}

/// Marks a case diverged the way the runner does: a diverged repetition, no usable summary, garbage numbers.
inline void diverge(CaseResult& c, int step) {
  c.status = "diverged";
  RepetitionResult r;
  r.repetition = static_cast<int>(c.repetitions.size());
  r.status = "diverged";
  r.diverged_step = step;
  r.diverged_reason = "non-finite position";
  r.mean_step_ms = NAN;
  c.repetitions.push_back(r);
  c.mean_nodes = NAN;
  c.step_ms.median = 1e9;  // must never be averaged in
}

/// An operation sample.
inline OpSample op(OpKind kind, std::int32_t node_ns, std::int32_t link_ns, std::int32_t nodes, std::int32_t links) {
  return OpSample{kind, node_ns, link_ns, nodes, links};
}

}  // namespace tcsb::testing
