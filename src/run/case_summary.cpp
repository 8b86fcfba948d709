#include "run/case_summary.h"

#include "analysis/statistics.h"

namespace tcsb {

void summarize_case(CaseResult& c) {
  c.status = "ok";
  std::vector<double> means, nodes, links, interps, feedback, feedback_total;
  std::vector<double> bullet, feedback_only, operations, blending;
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
    bullet.push_back(r.breakdown.bullet_ms);
    feedback_only.push_back(r.breakdown.feedback_ms);
    operations.push_back(r.breakdown.operations_ms);
    blending.push_back(r.breakdown.blending_ms);
  }
  c.step_ms = summarize(means);
  c.mean_nodes = mean_of(nodes);
  c.mean_links = mean_of(links);
  c.mean_interpolations = mean_of(interps);
  c.mean_feedback_ms = mean_of(feedback);
  c.mean_feedback_total_ms = mean_of(feedback_total);
  c.breakdown = {median(bullet), median(feedback_only), median(operations), median(blending)};
}

}  // namespace tcsb
