#include "report/shard_section.h"

#include "report/json_report.h"

namespace tcsb {

using ojson = nlohmann::ordered_json;

ojson merge_data_json(const RunResult& result) {
  ojson samples = ojson::object(), breakdowns = ojson::object();
  for (const CaseResult& c : result.cases) {
    // The breakdown's per-repetition parts: a case summarises them by their median, which a merge of repetitions
    // from several shards can only recompute from the parts themselves.
    ojson parts = ojson::array();
    for (const RepetitionResult& r : c.repetitions) {
      const StepBreakdown& b = r.breakdown;
      parts.push_back({json_number(b.bullet_ms), json_number(b.feedback_ms), json_number(b.operations_ms),
                       json_number(b.blending_ms)});
    }
    breakdowns[c.label] = std::move(parts);
    if (c.key.method != Method::kTcsb) continue;
    ojson columns = ojson::object();
    for (const char* name : kMergeSampleColumns) columns[name] = ojson::array();
    ojson work = ojson::object();
    for (int w = 0; w < kOpWorkCountKinds; ++w) work[op_work_count_name(OpWorkCount(w))] = ojson::array();
    for (const OpSample& s : c.ops.samples) {
      columns["kind"].push_back(static_cast<int>(s.kind));
      columns["node_ns"].push_back(s.node_ns);
      columns["link_ns"].push_back(s.link_ns);
      columns["nodes"].push_back(s.nodes);
      columns["links"].push_back(s.links);
      columns["interior"].push_back(s.work.interior ? 1 : 0);
      for (int w = 0; w < kOpWorkCountKinds; ++w) {
        work[op_work_count_name(OpWorkCount(w))].push_back(op_work_count(s.work, OpWorkCount(w)));
      }
    }
    columns["work"] = std::move(work);
    samples[c.label] = std::move(columns);
  }
  return {{"suite_file", result.suite.source}, {"op_samples", std::move(samples)}, {"breakdown_ms", breakdowns}};
}

ojson shard_json(const RunResult& result, const RunTables& tables) {
  ojson doc = native_json(result, tables);
  if (result.shard) {
    doc["context"]["shard"] = {
        {"k", result.shard->k}, {"n", result.shard->n}, {"split", split_name(result.shard->split)}};
    doc["merge_data"] = merge_data_json(result);  // what `tcsb merge` needs beyond the summaries
  }
  return doc;
}

}  // namespace tcsb
