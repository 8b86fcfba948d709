#include "fidelity/calibration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "analysis/fidelity_metrics.h"
#include "analysis/line_search.h"
#include "case/body_factory.h"
#include "fidelity/reconstruction.h"
#include "net/grid_resample.h"
#include "softbody/divergence.h"

namespace tcsb {

namespace {

/// The reference's positions at every measured step (floats, as Bullet's).
struct Trajectory {
  std::size_t nodes = 0;
  std::vector<std::array<float, 3>> frames;  // step s - warmup: [f * nodes, (f + 1) * nodes)
  void frame(std::size_t f, std::vector<Eigen::Vector3d>& x) const {
    x.resize(nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
      const std::array<float, 3>& p = frames[f * nodes + i];
      x[i] = Eigen::Vector3d(p[0], p[1], p[2]);
    }
  }
};

Trajectory record_reference(const Suite& suite, const std::shared_ptr<const Net>& fine) {
  SceneWorld world(suite.world, suite.scene);
  const Body reference = make_body(suite, {.kind = BodyKind::kPlain}, world, fine, suite.seed);
  const btSoftBody& body = *reference.bullet;
  const Net& net = *fine;
  Trajectory t;
  t.nodes = net.node_count();
  std::vector<Eigen::Vector3d> x;
  for (int s = 0; s < suite.warmup_steps + suite.steps; ++s) {
    world.step(static_cast<btScalar>(suite.world.dt));
    if (divergence_now(body, net.extent()))
      throw std::runtime_error("calibrate: the reference diverged on net \"" + net.spec().name + "\"");
    if (s < suite.warmup_steps) continue;
    copy_positions(body, x);
    for (const Eigen::Vector3d& p : x)
      t.frames.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
  }
  return t;
}

/// Steps `body` (attached to `world`) through the suite's steps and returns the mean over measured steps of the RMS (%
/// of the extent) of the surface `reconstruct` gives against the reference; infinity when the body diverges.
template <class Reconstruct>
double mean_rms(const Suite& suite, const Net& net, SceneWorld& world, const btSoftBody& body,
                const Trajectory& reference, Reconstruct reconstruct) {
  std::vector<Eigen::Vector3d> surface, ref;
  double sum = 0;
  for (int s = 0; s < suite.warmup_steps + suite.steps; ++s) {
    world.step(static_cast<btScalar>(suite.world.dt));
    if (divergence_now(body, net.extent())) return std::numeric_limits<double>::infinity();
    if (s < suite.warmup_steps) continue;
    reconstruct(surface);
    reference.frame(static_cast<std::size_t>(s - suite.warmup_steps), ref);
    sum += 100.0 / net.extent() * surface_error(surface, ref).rms;
  }
  return sum / suite.steps;
}

/// A TC-SB body coarsened to `level` with `stiffness` for its levels, against the reference.
double level_error(const Suite& suite, const std::shared_ptr<const Net>& net, const Trajectory& reference, int level,
                   const std::vector<double>& stiffness) {
  Suite trial = suite;
  trial.tcsb.level_stiffness = stiffness;
  SceneWorld world(suite.world, suite.scene);
  // At full budget: no controller, the cut stays at `level`.
  const Body body = make_body(trial, {.kind = BodyKind::kTcsb, .whole_level = level}, world, net, suite.seed);
  return mean_rms(suite, *net, world, *body.bullet, reference,
                  [&](std::vector<Eigen::Vector3d>& out) { reconstruct_leaves(*body.tc, out); });
}

/// The uniform grid of a budget with material stiffness `k`, against the reference.
double uniform_error(const Suite& suite, const std::shared_ptr<const Net>& fine, const Trajectory& reference,
                     double compression, double k) {
  Suite trial = suite;
  trial.solver.linear_stiffness = k;
  SceneWorld world(suite.world, suite.scene);
  const Body body = make_body(trial, {.kind = BodyKind::kUniform, .compression = compression}, world, fine, suite.seed);
  const Net& net = *fine;
  const Net& coarse = *body.net;
  std::vector<Eigen::Vector3d> x;
  return mean_rms(suite, net, world, *body.bullet, reference, [&](std::vector<Eigen::Vector3d>& out) {
    copy_positions(*body.bullet, x);
    out.resize(net.node_count());
    resample_bilinear({coarse.width(), coarse.height()}, x, {net.width(), net.height()}, out);
  });
}

/// Mean over nets of `error(net index)`.
template <class Error>
double mean_over_nets(std::size_t nets, Error error) {
  double sum = 0;
  for (std::size_t n = 0; n < nets; ++n) sum += error(n);
  return sum / static_cast<double>(nets);
}

StiffnessFit fit(const CalibrationSearch& search, double uncalibrated_k, const std::function<double(double)>& error) {
  StiffnessFit f;
  const LineMinimum m = minimize_on_interval(error, search.lo, search.hi, search.scan_points, search.tolerance);
  f.linear_stiffness = m.x;
  f.rms_pct = m.value;
  f.uncalibrated_rms_pct = error(uncalibrated_k);
  f.evaluations = m.evaluations + 1;
  return f;
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << v;
  return s.str();
}

}  // namespace

std::vector<StiffnessFit> evaluate_calibration(const Calibration& calibration, const Suite& suite,
                                               const std::vector<std::shared_ptr<const Net>>& nets) {
  std::vector<Trajectory> references;
  for (const auto& net : nets) references.push_back(record_reference(suite, net));
  const double base = suite.solver.linear_stiffness;
  const std::vector<double> stiffness = calibration.level_stiffness();
  const int levels = std::min(calibrated_level_count(nets, static_cast<int>(stiffness.size())),
                              static_cast<int>(calibration.levels.size()));
  std::vector<StiffnessFit> out;
  for (int level = 1; level <= levels; ++level) {
    const auto error = [&](const std::vector<double>& k) {
      return mean_over_nets(nets.size(),
                            [&](std::size_t n) { return level_error(suite, nets[n], references[n], level, k); });
    };
    StiffnessFit f = calibration.levels[static_cast<std::size_t>(level - 1)];
    f.rms_pct = error(stiffness);
    f.uncalibrated_rms_pct = error({});
    f.evaluations = 2;
    out.push_back(f);
  }
  for (StiffnessFit f : calibration.uniform_grid) {
    if (std::find(suite.compression.begin(), suite.compression.end(), f.compression) == suite.compression.end())
      continue;
    const auto error = [&](double k) {
      return mean_over_nets(nets.size(), [&](std::size_t n) {
        return uniform_error(suite, nets[n], references[n], f.compression, k);
      });
    };
    f.rms_pct = error(f.linear_stiffness);
    f.uncalibrated_rms_pct = error(base);
    f.evaluations = 2;
    out.push_back(f);
  }
  return out;
}

int calibrated_level_count(const std::vector<std::shared_ptr<const Net>>& nets, int max_levels) {
  std::vector<NetSpec> specs;
  for (const auto& net : nets) specs.push_back(net->spec());
  return calibrated_level_count(specs, max_levels);
}

Calibration calibrate_suite(const Suite& suite, const std::vector<std::shared_ptr<const Net>>& nets,
                            const CalibrationSearch& search, const CalibrationProgress& progress) {
  Calibration c;
  c.suite = suite.name;
  c.key = calibration_key(suite);
  c.piterations = suite.solver.piterations;
  c.linear_stiffness = suite.solver.linear_stiffness;
  std::vector<Trajectory> references;
  for (const auto& net : nets) references.push_back(record_reference(suite, net));
  const double base = suite.solver.linear_stiffness;
  const auto report = [&](const std::string& what, const StiffnessFit& f) {
    if (progress)
      progress(what + ": kLST " + fixed(f.linear_stiffness, 3) + ", RMS " + fixed(f.rms_pct, 3) + " % (uncalibrated " +
               fixed(f.uncalibrated_rms_pct, 3) + " %), " + std::to_string(f.evaluations) + " evaluations");
  };
  const int levels = calibrated_level_count(nets, search.max_levels);
  std::vector<double> fitted;
  for (int level = 1; level <= levels; ++level) {
    StiffnessFit f = fit(search, base, [&](double k) {
      std::vector<double> stiffness = fitted;
      stiffness.push_back(k);
      return mean_over_nets(nets.size(), [&](std::size_t n) {
        return level_error(suite, nets[n], references[n], level, stiffness);
      });
    });
    f.level = level;
    fitted.push_back(f.linear_stiffness);
    c.levels.push_back(f);
    report("level " + std::to_string(level), f);
  }
  std::vector<double> targets;
  for (const double t : suite.compression)
    if (t < 1.0) targets.push_back(t);
  std::sort(targets.begin(), targets.end());
  for (const double t : targets) {
    StiffnessFit f = fit(search, base, [&](double k) {
      return mean_over_nets(nets.size(),
                            [&](std::size_t n) { return uniform_error(suite, nets[n], references[n], t, k); });
    });
    f.compression = t;
    c.uniform_grid.push_back(f);
    report("uniform grid at " + fixed(100 * t, 0) + " %", f);
  }
  return c;
}

}  // namespace tcsb
