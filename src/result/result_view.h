// ResultView: a native result file (what `tcsb run` writes) read back into typed values, for the commands that
// work on finished runs (`tcsb compare`, `tcsb export`). Reading checks every field it uses and names the file and
// the field when one is missing or has the wrong type, so a bad file is one clear error line, never a crash.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/input_error.h"

namespace tcsb {

/// One repetition of one case as the file records it.
struct RepetitionView {
  int repetition = 0;
  std::string status;  ///< "ok" or "diverged"
  std::optional<int> diverged_step;
  std::optional<double> mean_step_ms;  ///< > 0; null in the file (diverged) -> nullopt, never when "ok"
  std::optional<double> mean_nodes, mean_links, mean_interpolations;
  std::int64_t operations = 0;
  std::string final_state_hash;
  int process = 0;  ///< the shard that measured it in a merged result (`process`); 0: the file's one process
};

/// A case's instruction counts (`tcsb run --measure instructions`): its timed steps' instructions over its ok
/// repetitions, by part, and the functions with the most own instructions, most first.
struct InstructionsView {
  std::int64_t own = 0, bullet = 0, total = 0;
  std::vector<std::pair<std::string, std::int64_t>> functions;  ///< (name, own instructions)
};

/// One case as the file records it (the fields the comparison and the exports use).
struct CaseView {
  std::string label, net, method;  ///< e.g. "n33/tcsb@0.3", "n33", "tcsb"
  std::string configuration;       ///< configuration.label of a suite with axes ("piterations=8"); "" without
  std::optional<double> compression;
  /// net_nodes: the net's grid nodes; nullopt when the document has none (hand-made documents; a file `tcsb run`
  /// wrote always has it, and its schema requires it)
  std::optional<std::int64_t> net_nodes;
  std::string status;
  std::optional<double> mean_nodes, mean_links, mean_interpolations;
  /// step_ms, the run's summary of the ok repetitions' mean step times: its count (0 when a hand-made document has
  /// none), mean, median, stddev and cv.
  std::int64_t step_ms_count = 0;
  std::optional<double> mean_step_ms;
  std::optional<double> median_step_ms;
  std::optional<double> stddev_step_ms;
  std::optional<double> cv_step_ms;
  /// ratio_vs_plain, the run's median of the case's step time over its plain case's, paired by repetition
  /// (base/case_pairing.h); nullopt without a plain case or in a hand-made document without it.
  std::optional<double> ratio_vs_plain;
  std::vector<RepetitionView> repetitions;
  std::optional<InstructionsView> instructions;  ///< `instructions`, when the run counted them
};

/// A whole result file.
struct ResultView {
  std::string file;  ///< the name used in errors
  int schema_version = 0;
  std::string measure = "time";    ///< "time" or "instructions" (`measure`; absent in older files: time)
  nlohmann::ordered_json context;  ///< as recorded (an object)
  nlohmann::ordered_json suite;    ///< as recorded (an object), a setting added since filled in with its default
  int steps = 0;                   ///< suite.steps: timed steps per repetition
  int repetitions = 0;             ///< suite.repetitions
  std::vector<CaseView> cases;
};

/// Throws InputError naming `file` unless `doc` is a tcsb document: a JSON object whose "tool" is "tcsb". The one
/// check of a result's "tool" field, for every reader of results and shards (a calibration file, which suite/ reads,
/// checks its own).
void check_tcsb_document(const nlohmann::ordered_json& doc, const std::string& file);

/// Reads a parsed native result document. Throws InputError (naming `file` and the field) when it is not a
/// tcsb result (check_tcsb_document), a field the readers use is missing or of the wrong type, or a value no run
/// can produce: a repetition's mean_step_ms <= 0, or null where its status is "ok"; a negative N, L or I (mean
/// nodes, links, interpolations) or step_ms median, stddev or cv.
ResultView read_result(const nlohmann::ordered_json& doc, const std::string& file);

/// The plain case of the same net and configuration as cases[index], or nullopt.
std::optional<std::size_t> plain_case_of(const ResultView& result, std::size_t index);

/// The plain_equal case of the same net, configuration and compression as the TC-SB case cases[index] (its static
/// body of the same node budget), or nullopt (cases[index] is not TC-SB with a compression, or the run has none).
std::optional<std::size_t> equal_plain_case_of(const ResultView& result, std::size_t index);

/// One repetition number's mean step times (ms) in two cases of one run: the case's and its base case's.
struct PairedStepTimes {
  double case_ms = 0;
  double base_ms = 0;
  int process = 0;  ///< the process that measured both (RepetitionView::process)
};

/// The mean step times of cases[index] and `base_index`, one pair per repetition number that is ok in both with a
/// time, in the case's repetition order.
std::vector<PairedStepTimes> paired_step_times(const ResultView& result, std::size_t index, std::size_t base_index);

/// Values of one case, one per repetition, each with the process that measured it (RepetitionView::process).
struct MeasuredValues {
  std::vector<double> values;
  std::vector<int> process;  ///< per value
};

/// Same-run ratios of cases[index] to `base_index`, one per repetition number that is ok in both with finite
/// times and a non-zero base: case.mean_step_ms[r] / base.mean_step_ms[r], in the case's repetition order
/// (the pairs of paired_step_times), with their processes.
MeasuredValues paired_step_ratio_values(const ResultView& result, std::size_t index, std::size_t base_index);

/// paired_step_ratio_values' values alone.
std::vector<double> paired_step_ratios(const ResultView& result, std::size_t index, std::size_t base_index);

/// The mean step times of the ok repetitions of cases[index], in repetition order, with their processes.
MeasuredValues ok_step_time_values(const CaseView& c);

/// ok_step_time_values' values alone.
std::vector<double> ok_step_times(const CaseView& c);

}  // namespace tcsb
