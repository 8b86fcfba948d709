// The work of each TreeCut operation (OpWork) is bounded by softbody/op_work_bounds.h and does not grow with the net:
// TC-SB bodies at the scaling suite's sizes (suites/scaling.json, 33^2 .. 1025^2 nodes) driven by RandomPolicy
// through a share of their net, every count's maximum (relocations included) within its bound, and each block-local
// count's maximum the same (within 5 %) on every size. Interior means are printed, not asserted (see below).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "feedback/random_policy.h"
#include "paper/op_work.h"
#include "paper/op_work_claims.h"
#include "scene/scene_world.h"
#include "softbody/op_work_bounds.h"
#include "softbody/tc_softbody_impl.h"
#include "suite/suite.h"

namespace tcsb {
namespace {

const std::filesystem::path kSourceDir = TCSB_SOURCE_DIR;

// A Debug or sanitizer build runs ~10-50x slower and the 1025^2 body alone takes about a gigabyte: those builds stop
// at 129^2 (still three sizes, 16x growth in nodes), and say so in the test's output. (Release, loaded machine: about
// 20 s for all six sizes.)
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
constexpr int kLargestWidth = 1025;
#else
constexpr int kLargestWidth = 129;
#endif

class TallySink final : public OpSink {
 public:
  void record(const OpSample& sample) override { tally.add(sample); }
  OpWorkTally tally;
};

/// Drives the body with RandomPolicy for 60 steps: 20 coarsening as far as it goes, 20 refining back, 20 coarsening
/// again, at most N/32 operations begun per step but never more than 1024, so that the small nets reach every level
/// and the largest sees about 120 000 operations (a share of it) and the test stays fast. Operations only: no Bullet
/// step (the counts do not depend on positions, except the DBVT walk, which this test reports but the bounds leave
/// out).
OpWorkTally drive(const NetSpec& spec, const Suite& suite) {
  auto net = std::make_shared<const Net>(spec);
  SceneWorld world(suite.world);
  TcSoftBody body(world.info(), net, suite.solver, suite.tcsb);
  TallySink sink;
  body.impl().set_op_sink(&sink);
  RandomPolicy policy(1);
  const int n = static_cast<int>(net->node_count());
  const int per_step = std::clamp(n / 32, 8, 1024);
  for (int s = 0; s < 60; ++s) {
    body.advance_blends();
    policy.apply(body, (s / 20) % 2 == 0 ? 0 : n, per_step);
  }
  for (int s = 0; s <= body.settings().blend_steps; ++s) body.advance_blends();  // end what is blending
  body.impl().set_op_sink(nullptr);
  // validate() is O(N log N): seconds on the largest nets, where the property tests have checked the same code.
  if (spec.width <= 257) {  // braces: EXPECT_* expands to an if/else of its own
    EXPECT_TRUE(body.validate().ok()) << spec.name << ": " << body.validate().summary();
  }
  return sink.tally;
}

bool contains(std::span<const OpWorkCount> counts, OpWorkCount count) {
  return std::find(counts.begin(), counts.end(), count) != counts.end();
}

TEST(OpWorkScaling, EveryCountIsBoundedAndTheBlockLocalOnesAreTheSameOnEverySize) {
  const Suite suite = parse_suite(kSourceDir / "suites/scaling.json");
  std::map<std::string, OpWorkTally> tallies;
  std::vector<std::string> order;
  for (const NetSpec& spec : suite.nets) {
    if (spec.width > kLargestWidth) {
      std::cout << "[ SKIPPED  ] " << spec.name << ": larger than " << kLargestWidth
                << "^2 in a Debug or sanitizer build\n";
      continue;
    }
    tallies.emplace(spec.name, drive(spec, suite));
    order.push_back(spec.name);
  }
  ASSERT_GE(order.size(), 3u);
  for (int k = 0; k < kOpKindCount; ++k) {
    const auto kind = static_cast<OpKind>(k);
    const OpWork& bound = op_work_bounds::bound(kind);
    for (int c = 0; c < kOpWorkCountKinds; ++c) {
      const auto count = static_cast<OpWorkCount>(c);
      std::cout << op_kind_name(kind) << " " << op_work_count_name(count) << ":";
      for (const std::string& name : order) {
        const OpWorkSummary s = tallies.at(name).summary(kind);
        std::cout << "  " << name << " max " << s[count].max << " mean " << s[count].mean << " interior "
                  << s[count].interior_mean << " (" << s.interior_calls << "/" << s.calls << ")";
      }
      std::cout << "  bound " << op_work_count(bound, count) << "\n";
      if (!contains(kOpWorkBoundedCounts, count)) continue;  // the DBVT walk: not bounded by the cut
      std::vector<double> maxima, interior_means;
      for (const std::string& name : order) {
        const OpWorkSummary s = tallies.at(name).summary(kind);
        ASSERT_GT(s.interior_calls, 0) << name << " " << op_kind_name(kind);
        EXPECT_LE(s[count].max, op_work_count(bound, count))
            << name << " " << op_kind_name(kind) << " " << op_work_count_name(count);
        maxima.push_back(s[count].max);
        interior_means.push_back(s[count].interior_mean);
      }
      if (!contains(kOpWorkBlockLocalCounts, count)) continue;  // relocations: whatever is last in the arrays
      // The same worst case on every size (the claims' 5 %).
      EXPECT_LE(relative_spread(maxima), kOpWorkSpreadTolerance)
          << op_kind_name(kind) << " " << op_work_count_name(count) << " maxima";
      // Interior means are reported, not asserted, here: this driver does not give every size the same workload.
      // With at most 1024 operations begun per step, 513^2 and 1025^2 never coarsen past the first levels (40 x 1024
      // coarse calls, the cap, where 257^2 ran out at 28927), so their interior blocks mostly sit in a uniform fine
      // cut (inferred from the call counts, not broken down by level here): coarse's interior links mean is 25.9 on
      // 33^2..257^2 (within 0.3 %) and 27.0 / 27.7 on 513^2 / 1025^2. The runs the claim judges (paper, ci) drive every
      // net with the same budgets, and there the interior means agree within 2.3 %.
      std::cout << "  interior-mean spread " << relative_spread(interior_means) * 100 << " %\n";
    }
  }
}

}  // namespace
}  // namespace tcsb
