#include "run/case_summary.h"

#include "analysis/statistics.h"

namespace tcsb {

void summarize_case(CaseResult& c) {
  c.status = "ok";
  std::vector<double> means, nodes, links, interps, feedback, feedback_total;
  for (const RepetitionResult& r : c.repetitions) {
    if (r.status != "ok") {
      c.status = "diverged";
      continue;
    }
    means.push_back(r.mean_step_ms);
    nodes.push_back(r.mean_nodes);
    links.push_back(r.mean_links);
    interps.push_back(r.mean_interpolations);
    feedback.push_back(r.mean_feedback_ms);
    feedback_total.push_back(r.mean_feedback_total_ms);
  }
  c.step_ms = summarize(means);
  c.mean_nodes = mean_of(nodes);
  c.mean_links = mean_of(links);
  c.mean_interpolations = mean_of(interps);
  c.mean_feedback_ms = mean_of(feedback);
  c.mean_feedback_total_ms = mean_of(feedback_total);
}

}  // namespace tcsb
