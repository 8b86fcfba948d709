#include "run/runner.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "analysis/statistics.h"
#include "case/case_body.h"
#include "case/state_hash.h"
#include "case/step_clock.h"
#include "fidelity/fidelity_runner.h"
#include "run/case_summary.h"
#include "run/out_of_memory.h"
#include "softbody/divergence.h"
#include "suite/suite_axes.h"

namespace tcsb {

namespace {

/// Collects operation samples of timed steps only.
class OpRecorder final : public OpSink {
 public:
  explicit OpRecorder(std::vector<OpSample>& out) : out_(out) {}
  void record(const OpSample& sample) override {
    if (recording) out_.push_back(sample);
  }
  bool recording = false;

 private:
  std::vector<OpSample>& out_;
};

/// Where a repetition diverged: the step after which a check failed, why, and the body's state hash then.
struct Divergence {
  int step = 0;
  std::string reason;
  std::string state_hash;
};

/// The first step after which the repetition's body fails a divergence check. The timed loop checks fully only
/// every kFullCheckEvery steps (a full check reads every node and link: outside the timed region, but it would
/// leave them in the cache for the next timed step), so what it found at `found` may have begun after `clean`, the
/// last step that passed the full check. A repetition is deterministic (same seed, same steps: its final state
/// hash is gated), so replaying it up to `found` and checking fully after every step past `clean` finds the step
/// at which it began, whatever the run's length. If the replay does not diverge by then (a time budget,
/// feedback.max_step_ms, makes runs differ), what the run found stands.
Divergence first_divergence(const Suite& suite, const CaseKey& key, const std::shared_ptr<const Net>& net,
                            std::uint64_t seed, int clean, Divergence found) {
  SoftBodyWorld world(suite.world);
  std::unique_ptr<CaseBody> body = make_case_body(suite, key, world, net, seed);
  const btScalar dt = static_cast<btScalar>(suite.world.dt);
  for (int s = 0; s < found.step; ++s) {
    body->step(dt);
    if (s <= clean) continue;
    if (std::optional<std::string> reason = divergence_now(body->bullet(), net->extent()))
      return {s, *reason, state_hash(body->bullet())};
  }
  return found;
}

/// Adds one timed step to `sum`: the body's phases with the operations of the step (samples from `first` on) taken
/// out of the phase they ran in — begun ones (refine, coarse) out of the feedback stage, which begins them, ended
/// ones out of the blends, which end them. Without phases (a stock body) the whole step is Bullet's.
void add_step_breakdown(double step_ms, const StepPhases* phases, const std::vector<OpSample>& samples,
                        std::size_t first, StepBreakdown& sum) {
  if (!phases) {
    sum.bullet_ms += step_ms;
    return;
  }
  double begun_ms = 0, ended_ms = 0;
  for (std::size_t i = first; i < samples.size(); ++i) {
    const double ms = (static_cast<double>(samples[i].node_ns) + static_cast<double>(samples[i].link_ns)) / 1e6;
    const bool begins = samples[i].kind == OpKind::kRefine || samples[i].kind == OpKind::kCoarse;
    (begins ? begun_ms : ended_ms) += ms;
  }
  sum.bullet_ms += phases->bullet_ms;
  sum.feedback_ms += phases->feedback_ms - begun_ms;
  sum.operations_ms += begun_ms + ended_ms;
  sum.blending_ms += phases->blends_ms - ended_ms;
}

RepetitionResult run_repetition(const Suite& suite, const CaseKey& key, int repetition,
                                const std::shared_ptr<const Net>& net, std::uint64_t seed,
                                std::vector<OpSample>& op_samples) {
  RepetitionResult rep;
  rep.repetition = repetition;
  SoftBodyWorld world(suite.world);
  const StepClock::time_point built0 = StepClock::now();
  std::unique_ptr<CaseBody> body = make_case_body(suite, key, world, net, seed);
  rep.build_ms = ms_between(built0, StepClock::now());
  OpRecorder recorder(op_samples);
  if (TcSoftBody* tc = body->tc()) tc->set_op_sink(&recorder);

  const btScalar dt = static_cast<btScalar>(suite.world.dt);
  const int total = suite.warmup_steps + suite.steps;
  StepSeries& series = rep.series;
  // Every series reserved to its final size: no reallocation inside the timed loop, and the recorder takes the
  // bytes suite_memory.cpp counts (doubling growth would leave up to twice that allocated).
  const std::size_t timed_steps = static_cast<std::size_t>(suite.steps);
  for (std::vector<double>* v : {&series.step_ms, &series.feedback_ms, &series.feedback_total_ms})
    v->reserve(timed_steps);
  for (std::vector<std::int32_t>* v : {&series.nodes, &series.links, &series.interpolations}) v->reserve(timed_steps);
  const std::size_t ops_before = op_samples.size();
  StepBreakdown sum;  // over the timed steps

  for (int s = 0; s < total; ++s) {
    const bool timed = s >= suite.warmup_steps;
    recorder.recording = timed;
    const std::size_t ops_at_step = op_samples.size();
    const StepClock::time_point t0 = StepClock::now();
    body->step(dt);
    const StepClock::time_point t1 = StepClock::now();
    const btSoftBody& b = body->bullet();
    if (timed) {
      series.step_ms.push_back(ms_between(t0, t1));
      series.nodes.push_back(b.m_nodes.size());
      series.links.push_back(b.m_links.size());
      series.interpolations.push_back(body->interpolations());
      const FeedbackCost cost = body->feedback_cost();
      series.feedback_ms.push_back(cost.critical_ms);
      series.feedback_total_ms.push_back(cost.total_ms);
      add_step_breakdown(series.step_ms.back(), body->phases(), op_samples, ops_at_step, sum);
    }
    const std::optional<std::string> diverged = divergence_after_step(b, net->extent(), s, total);  // untimed
    if (diverged) {
      const Divergence first =
          first_divergence(suite, key, net, seed, last_full_check_before(s), {s, *diverged, state_hash(b)});
      rep.status = "diverged";
      rep.diverged_step = first.step;
      rep.diverged_reason = first.reason;
      rep.final_state_hash = first.state_hash;
      break;
    }
  }
  if (TcSoftBody* tc = body->tc()) tc->set_op_sink(nullptr);
  rep.operations = static_cast<std::int64_t>(op_samples.size() - ops_before);
  if (rep.status == "ok") rep.final_state_hash = state_hash(body->bullet());
  if (!series.step_ms.empty()) {
    rep.mean_step_ms = mean(series.step_ms);
    rep.median_step_ms = median(series.step_ms);
  }
  rep.mean_nodes = mean_of(series.nodes);
  rep.mean_links = mean_of(series.links);
  rep.mean_interpolations = mean_of(series.interpolations);
  rep.mean_feedback_ms = mean_of(series.feedback_ms);
  rep.mean_feedback_total_ms = mean_of(series.feedback_total_ms);
  if (!series.step_ms.empty()) {
    const double steps = static_cast<double>(series.step_ms.size());
    rep.breakdown = {sum.bullet_ms / steps, sum.feedback_ms / steps, sum.operations_ms / steps,
                     sum.blending_ms / steps};
  }
  return rep;
}

/// The nets of a suite, built once per call (they are immutable and shared by every case of the net); a net not
/// the suite does not run here (Suite::run_units) is not built (null): a shard must not pay for another's largest net.
std::vector<std::shared_ptr<const Net>> build_nets(const Suite& suite) {
  std::vector<std::shared_ptr<const Net>> nets;
  nets.reserve(suite.nets.size());
  for (std::size_t i = 0; i < suite.nets.size(); ++i) {
    const NetSpec& spec = suite.nets[i];
    if (!runs_net(suite, i)) {
      nets.push_back(nullptr);
      continue;
    }
    nets.push_back(naming_out_of_memory("suite " + suite.name + ", net " + spec.name,
                                        [&spec] { return std::make_shared<const Net>(spec); }));
  }
  return nets;
}

/// Runs the planned repetitions into result.cases, numbering each `first_repetition[case] + run.repetition`.
void run_plan(RunResult& result, const std::vector<PlannedRun>& plan, const std::vector<int>& first_repetition,
              const std::vector<std::shared_ptr<const Net>>& nets, const RunOptions& options, int& done, int total) {
  // Each case runs with its configuration's settings (the suite's own without axes), and draws the seed it has in
  // that configuration run alone: a configuration of a suite with axes is that suite without them.
  const std::vector<Suite> settings = configuration_suites(result.suite);
  std::vector<std::uint64_t> seeds;
  const std::size_t per_configuration = cases_per_configuration(result.suite);
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const std::size_t index = index_in_configuration(per_configuration, i);
    seeds.push_back(case_seed(settings[result.cases[i].key.configuration], index));
  }
  for (const PlannedRun& run : plan) {
    CaseResult& c = result.cases[run.case_index];
    // One seed per case, the same for every repetition: repetitions do identical work, so their spread is the
    // machine's, and N, L, I and the final state are exact, gateable numbers.
    const std::uint64_t seed = seeds[run.case_index];
    const int repetition = first_repetition[run.case_index] + run.repetition;
    const Suite& suite = settings[c.key.configuration];
    c.repetitions.push_back(
        naming_out_of_memory("suite " + result.suite.name + ", case " + c.label + " (net " + c.net_name + ")", [&] {
          return run_repetition(suite, c.key, repetition, nets[c.key.net], seed, c.ops.samples);
        }));
    ++done;
    if (options.progress) options.progress(done, total, c.label);
  }
}

}  // namespace

RunResult run_suite(const Suite& suite, const Context& context, const RunOptions& options) {
  const StepClock::time_point start = StepClock::now();
  RunResult result;
  result.suite = suite;
  result.context = context;
  const std::vector<CaseKey> keys = expand_cases(suite);
  std::vector<PlannedRun> plan = interleaved_plan(suite, keys);
  // A shard runs the whole suite's plan restricted to its nets: the order among its cases is the unsharded one.
  std::erase_if(plan, [&](const PlannedRun& run) {
    return !runs_unit(suite, keys[run.case_index].configuration, keys[run.case_index].net);
  });

  const std::vector<std::shared_ptr<const Net>> nets = build_nets(suite);

  result.cases.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    CaseResult& c = result.cases[i];
    c.key = keys[i];
    if (!runs_unit(suite, keys[i].configuration, keys[i].net)) continue;  // another shard's case: dropped below
    const Net& net = *nets[keys[i].net];
    c.label = case_label(suite, keys[i]);
    c.net_name = net.spec().name;
    c.net_nodes = static_cast<std::int64_t>(net.node_count());
    c.net_links = static_cast<std::int64_t>(net.links().size());
    c.target_nodes = target_node_count(net, keys[i]);
  }

  // The fidelity pass runs after every timed repetition, one pass per net, so it cannot disturb their timings.
  const bool fidelity = !fidelity_plan(suite).empty();
  const auto built = static_cast<std::size_t>(std::count_if(nets.begin(), nets.end(), [](const auto& n) { return n; }));
  const int total = static_cast<int>(plan.size() + (fidelity ? built : 0));
  int done = 0;
  run_plan(result, plan, std::vector<int>(keys.size(), 0), nets, options, done, total);
  for (CaseResult& c : result.cases) summarize_case(c);
  // Only now, when no index into result.cases is needed any more: drop the cases of nets this process did not run.
  std::erase_if(result.cases, [&](const CaseResult& c) { return !runs_unit(suite, c.key.configuration, c.key.net); });
  if (fidelity) {
    result.fidelity = naming_out_of_memory("suite " + suite.name + ", fidelity pass", [&] {
      return run_fidelity(suite, nets, [&](const std::string& net) {
        ++done;
        if (options.progress) options.progress(done, total, net + "/fidelity");
      });
    });
  }
  result.wall_s = std::chrono::duration<double>(StepClock::now() - start).count();
  return result;
}

void run_more_repetitions(RunResult& result, const std::vector<std::size_t>& case_indices, int extra,
                          const RunOptions& options) {
  if (extra <= 0) return;
  const StepClock::time_point start = StepClock::now();
  std::vector<bool> chosen(result.cases.size(), false);
  for (const std::size_t i : case_indices)
    if (i < chosen.size()) chosen[i] = true;
  std::vector<CaseKey> keys;
  std::vector<int> first_repetition;
  for (const CaseResult& c : result.cases) {
    keys.push_back(c.key);
    int next = 0;  // after the case's highest repetition number
    for (const RepetitionResult& r : c.repetitions) next = std::max(next, r.repetition + 1);
    first_repetition.push_back(next);
  }
  // The run's own order for `extra` repetitions, keeping only the chosen cases: nets rotate, a net's cases stay
  // side by side in suite order.
  Suite more = result.suite;
  more.repetitions = extra;
  std::vector<PlannedRun> plan = interleaved_plan(more, keys);
  std::erase_if(plan, [&](const PlannedRun& run) { return !chosen[run.case_index]; });
  if (plan.empty()) return;
  const std::vector<std::shared_ptr<const Net>> nets = build_nets(result.suite);
  int done = 0;
  run_plan(result, plan, first_repetition, nets, options, done, static_cast<int>(plan.size()));
  for (std::size_t i = 0; i < result.cases.size(); ++i)
    if (chosen[i]) summarize_case(result.cases[i]);
  result.wall_s += std::chrono::duration<double>(StepClock::now() - start).count();
}

}  // namespace tcsb
