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
#include "softbody/tc_softbody_impl.h"
#include "suite/scene_bodies.h"
#include "suite/suite_axes.h"
#include "world/world_runner.h"

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
  SceneWorld world(suite.world, suite.scene);
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

/// One repetition of one case while it runs: its body, what it recorded so far and how far it got. Steps run as
/// the caller asks: all at once (run_repetition), or in blocks beside the net's other cases (run_side_by_side).
class RepetitionRun {
 public:
  RepetitionRun(const Suite& suite, const CaseKey& key, int repetition, std::shared_ptr<const Net> net,
                std::uint64_t seed, std::vector<OpSample>& op_samples, Measure measure)
      : suite_(suite), key_(key), net_(std::move(net)), seed_(seed), world_(suite.world, suite.scene),
        op_samples_(op_samples), recorder_(op_samples), total_(static_cast<int>(steps_per_repetition(suite))),
        ops_before_(op_samples.size()) {
    rep_.repetition = repetition;
    const StepClock::time_point built0 = StepClock::now();
    body_ = make_case_body(suite, key, world_, net_, seed);
    rep_.build_ms = ms_between(built0, StepClock::now());
    if (TcSoftBody* tc = body_->tc()) tc->impl().set_op_sink(&recorder_);
    if (measure == Measure::kInstructions) body_->set_meter(&meter_.emplace());
    // Every series reserved to its final size: no reallocation inside the timed loop, and the recorder takes the
    // bytes suite_memory.cpp counts (doubling growth would leave up to twice that allocated).
    StepSeries& series = rep_.series;
    const std::size_t timed_steps = static_cast<std::size_t>(suite.steps);
    for (std::vector<double>* v : {&series.step_ms, &series.feedback_ms, &series.feedback_total_ms})
      v->reserve(timed_steps);
    for (std::vector<std::int32_t>* v : {&series.nodes, &series.links, &series.interpolations}) v->reserve(timed_steps);
  }
  ~RepetitionRun() {
    if (TcSoftBody* tc = body_->tc()) tc->impl().set_op_sink(nullptr);
    body_->set_meter(nullptr);
  }
  RepetitionRun(const RepetitionRun&) = delete;
  RepetitionRun& operator=(const RepetitionRun&) = delete;

  /// Timed steps still to run (0 once diverged).
  int timed_left() const {
    return rep_.status == "ok" ? suite_.steps - static_cast<int>(rep_.series.step_ms.size()) : 0;
  }

  void warm_up() {
    while (rep_.status == "ok" && step_ < suite_.warmup_steps) step_once(false);
  }
  /// Up to `count` steps, timed or not (a step that is not timed records no operation either).
  void run(int count, bool timed) {
    for (int i = 0; i < count && timed_left() > 0; ++i) step_once(timed);
  }
  void pause() { body_->pause(); }
  void resume() { body_->resume(); }

  RepetitionResult finish() && {
    const StepSeries& series = rep_.series;
    rep_.operations = static_cast<std::int64_t>(op_samples_.size() - ops_before_);
    if (meter_) rep_.metered = meter_->parts();
    if (rep_.status == "ok") rep_.final_state_hash = state_hash(body_->bullet());
    if (!series.step_ms.empty()) {
      rep_.mean_step_ms = mean(series.step_ms);
      rep_.median_step_ms = median(series.step_ms);
    }
    rep_.mean_nodes = mean_of(series.nodes);
    rep_.mean_links = mean_of(series.links);
    rep_.mean_interpolations = mean_of(series.interpolations);
    rep_.mean_feedback_ms = mean_of(series.feedback_ms);
    rep_.mean_feedback_total_ms = mean_of(series.feedback_total_ms);
    if (!series.step_ms.empty()) {
      const double steps = static_cast<double>(series.step_ms.size());
      rep_.breakdown = {sum_.bullet_ms / steps, sum_.feedback_ms / steps, sum_.operations_ms / steps,
                        sum_.blending_ms / steps};
    }
    return std::move(rep_);
  }

 private:
  void step_once(bool timed) {
    recorder_.recording = timed;
    const std::size_t ops_at_step = op_samples_.size();
    const StepClock::time_point t0 = StepClock::now();
    if (timed && meter_) meter_->begin_step();
    body_->step(static_cast<btScalar>(suite_.world.dt));
    if (meter_) meter_->end_step();
    const StepClock::time_point t1 = StepClock::now();
    const btSoftBody& b = body_->bullet();
    if (timed) {
      StepSeries& series = rep_.series;
      series.step_ms.push_back(ms_between(t0, t1));
      series.nodes.push_back(b.m_nodes.size());
      series.links.push_back(b.m_links.size());
      series.interpolations.push_back(body_->interpolations());
      const FeedbackCost cost = body_->feedback_cost();
      series.feedback_ms.push_back(cost.critical_ms);
      series.feedback_total_ms.push_back(cost.total_ms);
      add_step_breakdown(series.step_ms.back(), body_->phases(), op_samples_, ops_at_step, sum_);
    }
    if (world_.scene().has_colliders()) count_penetrations(b);  // untimed
    const int s = step_++;
    const std::optional<std::string> diverged = divergence_after_step(b, net_->extent(), s, total_);  // untimed
    if (diverged) {
      const Divergence first =
          first_divergence(suite_, key_, net_, seed_, last_full_check_before(s), {s, *diverged, state_hash(b)});
      rep_.status = "diverged";
      rep_.diverged_step = first.step;
      rep_.diverged_reason = first.reason;
      rep_.final_state_hash = first.state_hash;
    }
  }

  void count_penetrations(const btSoftBody& b) {
    Penetrations& p = rep_.penetrations ? *rep_.penetrations : rep_.penetrations.emplace();
    ++p.steps;
    p.contact_node_steps += b.m_rcontacts.size();  // this step's: Bullet clears them as the next step begins
    for (int i = 0; i < b.m_nodes.size(); ++i) {
      const double depth = world_.penetration(b.m_nodes[i].m_x);
      if (!world_.penetrated(depth)) continue;
      ++p.node_steps;
      p.deepest_pct = std::max(p.deepest_pct, 100.0 * depth / net_->extent());
    }
  }

  const Suite& suite_;
  CaseKey key_;
  std::shared_ptr<const Net> net_;
  std::uint64_t seed_;
  SceneWorld world_;
  std::vector<OpSample>& op_samples_;
  OpRecorder recorder_;
  std::unique_ptr<CaseBody> body_;
  std::optional<InstructionMeter> meter_;  // measure kInstructions only
  // Every step the repetition takes (steps_per_repetition); an int, since a suite that runs has passed the memory
  // check, which counts a recorded sample per step.
  const int total_;
  const std::size_t ops_before_;
  int step_ = 0;  // steps taken so far, warm-up included
  RepetitionResult rep_;
  StepBreakdown sum_;  // over the timed steps
};

/// A repetition alone: warm-up, then every timed step.
RepetitionResult run_repetition(const Suite& suite, const CaseKey& key, int repetition,
                                const std::shared_ptr<const Net>& net, std::uint64_t seed,
                                std::vector<OpSample>& op_samples, Measure measure) {
  RepetitionRun run(suite, key, repetition, net, seed, op_samples, measure);
  run.warm_up();
  run.run(suite.steps, true);
  return std::move(run).finish();
}

/// The repetitions of one net's cases side by side (Suite::interleave_steps = k): each warms up alone, then they
/// take turns, each turn one untimed step (the body's data come back into the caches the others used) and k timed
/// steps, the case opening a round rotating. The machine's speed drifts within a repetition's fraction of a
/// second; so a slow moment falls on every case of the net alike, and their ratios keep little of it.
void run_side_by_side(std::vector<std::unique_ptr<RepetitionRun>>& runs, int block_steps) {
  for (auto& run : runs) {
    run->warm_up();
    run->pause();
  }
  for (std::size_t round = 0;; ++round) {
    bool any = false;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      RepetitionRun& run = *runs[(round + i) % runs.size()];
      if (run.timed_left() == 0) continue;
      any = true;
      run.resume();
      run.run(1, false);
      run.run(block_steps, true);
      run.pause();
    }
    if (!any) return;
  }
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
  const auto repetition_of = [&](const PlannedRun& run) { return first_repetition[run.case_index] + run.repetition; };
  const auto report = [&](const CaseResult& c) {
    ++done;
    if (options.progress) options.progress(done, total, c.label);
  };
  if (result.suite.interleave_steps == 0) {
    for (const PlannedRun& run : plan) {
      CaseResult& c = result.cases[run.case_index];
      // One seed per case, the same for every repetition: repetitions do identical work, so their spread is the
      // machine's, and N, L, I and the final state are exact, gateable numbers.
      const Suite& suite = settings[c.key.configuration];
      c.repetitions.push_back(
          naming_out_of_memory("suite " + result.suite.name + ", case " + c.label + " (net " + c.net_name + ")", [&] {
            return run_repetition(suite, c.key, repetition_of(run), nets[c.key.net], seeds[run.case_index],
                                  c.ops.samples, options.measure);
          }));
      report(c);
    }
    return;
  }
  // Side by side: a group is the plan's consecutive runs of one net in one repetition of the plan (interleaved_plan
  // keeps a net's cases of a repetition together, every configuration's), or of every net with
  // interleave_across_nets (the plan keeps a repetition's runs together).
  const bool across_nets = result.suite.interleave_across_nets;
  for (std::size_t first = 0; first < plan.size();) {
    const std::size_t net = result.cases[plan[first].case_index].key.net;
    std::size_t last = first + 1;
    while (last < plan.size() && plan[last].repetition == plan[first].repetition &&
           (across_nets || result.cases[plan[last].case_index].key.net == net))
      ++last;
    const std::string group = across_nets ? "repetition " + std::to_string(repetition_of(plan[first]) + 1)
                                          : "net " + result.cases[plan[first].case_index].net_name;
    naming_out_of_memory("suite " + result.suite.name + ", " + group + " side by side", [&] {
      std::vector<std::unique_ptr<RepetitionRun>> runs;
      for (std::size_t i = first; i < last; ++i) {
        CaseResult& c = result.cases[plan[i].case_index];
        runs.push_back(std::make_unique<RepetitionRun>(settings[c.key.configuration], c.key, repetition_of(plan[i]),
                                                       nets[c.key.net], seeds[plan[i].case_index], c.ops.samples,
                                                       options.measure));
      }
      run_side_by_side(runs, result.suite.interleave_steps);
      for (std::size_t i = first; i < last; ++i) {
        CaseResult& c = result.cases[plan[i].case_index];
        c.repetitions.push_back(std::move(*runs[i - first]).finish());
        report(c);
      }
    });
    first = last;
  }
}

}  // namespace

RunResult run_suite(const Suite& suite, const Context& context, const RunOptions& options) {
  const StepClock::time_point start = StepClock::now();
  RunResult result;
  result.measure = options.measure;
  result.suite = suite;
  result.context = context;
  const std::vector<CaseKey> keys = expand_cases(suite);
  std::vector<PlannedRun> plan = interleaved_plan(suite, keys);
  // A shard runs the whole suite's plan restricted to its units and repetitions: the order among its runs is the
  // unsharded one, a net's cases of a repetition still side by side.
  std::erase_if(plan, [&](const PlannedRun& run) {
    return !runs_repetition(suite, keys[run.case_index].configuration, keys[run.case_index].net, run.repetition);
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
  // One fidelity pass per net, in the process that runs the net's first repetition (with a split by repetition,
  // other shards build the net too but leave its pass to that one).
  std::vector<std::shared_ptr<const Net>> fidelity_nets = nets;
  for (std::size_t i = 0; i < fidelity_nets.size(); ++i)
    if (!runs_fidelity_of(suite, i)) fidelity_nets[i] = nullptr;
  const auto passes = static_cast<std::size_t>(
      std::count_if(fidelity_nets.begin(), fidelity_nets.end(), [](const auto& n) { return n; }));
  const int total = static_cast<int>(plan.size() + (fidelity ? passes : 0));
  int done = 0;
  run_plan(result, plan, std::vector<int>(keys.size(), 0), nets, options, done, total);
  for (CaseResult& c : result.cases) summarize_case(c);
  // Only now, when no index into result.cases is needed any more: drop the cases of nets this process did not run.
  std::erase_if(result.cases, [&](const CaseResult& c) { return !runs_unit(suite, c.key.configuration, c.key.net); });
  if (fidelity) {
    result.fidelity = naming_out_of_memory("suite " + suite.name + ", fidelity pass", [&] {
      return run_fidelity(suite, fidelity_nets, [&](const std::string& net) {
        ++done;
        if (options.progress) options.progress(done, total, net + "/fidelity");
      });
    });
  }
  // A scene of many bodies: after the timed cases of its nets, as the fidelity pass, by the process that runs the
  // first net's first repetition.
  if (is_world_suite(suite) && runs_fidelity_of(suite, 0))
    result.world = naming_out_of_memory("suite " + suite.name + ", world pass", [&] { return run_world(suite); });
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
