#include "report/op_work_json.h"

#include "harness/op_work.h"
#include "report/json_report.h"

namespace tcsb {

nlohmann::ordered_json op_work_json(std::span<const OpSample> samples) {
  using ojson = nlohmann::ordered_json;
  OpWorkTally tally;
  tally.add(samples);
  ojson out = ojson::object();
  for (int k = 0; k < kOpKindCount; ++k) {
    const auto kind = static_cast<OpKind>(k);
    const OpWorkSummary s = tally.summary(kind);
    ojson op = {{"calls", s.calls}};
    for (int c = 0; c < kOpWorkCountKinds; ++c) {
      const auto count = static_cast<OpWorkCount>(c);
      op[op_work_count_name(count)] = s.calls > 0 ? ojson{{"max", s[count].max}, {"mean", json_number(s[count].mean)}}
                                                  : ojson{{"max", nullptr}, {"mean", nullptr}};
    }
    out[op_kind_name(kind)] = std::move(op);
  }
  return out;
}

}  // namespace tcsb
