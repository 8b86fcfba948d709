#include "report/op_work_json.h"

#include "paper/op_work.h"
#include "report/json_number.h"

namespace tcsb {

nlohmann::ordered_json op_work_json(std::span<const OpSample> samples) {
  using ojson = nlohmann::ordered_json;
  OpWorkTally tally;
  tally.add(samples);
  ojson out = ojson::object();
  for (int k = 0; k < kOpKindCount; ++k) {
    const auto kind = static_cast<OpKind>(k);
    const OpWorkSummary s = tally.summary(kind);
    ojson op = {{"calls", s.calls}, {"interior_calls", s.interior_calls}};
    for (int c = 0; c < kOpWorkCountKinds; ++c) {
      const auto count = static_cast<OpWorkCount>(c);
      ojson stat = {{"max", nullptr}, {"mean", nullptr}, {"interior_mean", nullptr}};
      if (s.calls > 0) {
        stat["max"] = s[count].max;
        stat["mean"] = json_number(s[count].mean);
      }
      if (s.interior_calls > 0) stat["interior_mean"] = json_number(s[count].interior_mean);
      op[op_work_count_name(count)] = std::move(stat);
    }
    out[op_kind_name(kind)] = std::move(op);
  }
  return out;
}

}  // namespace tcsb
