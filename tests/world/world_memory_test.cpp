// The memory estimate of a scene of many bodies bounds the heap its world pass takes: every track's bodies, their
// nets, controllers and surfaces alive at once (suite/suite_memory.h, suite/world_plan.h), and a geomorph's jumps.
#include <gtest/gtest.h>

#include <algorithm>

#include "../suite/heap_in_use.h"
#include "suite/suite.h"
#include "suite/suite_memory.h"
#include "suite/world_plan.h"
#include "world/world_observer.h"
#include "world/world_runner.h"
#include "world_suite_json.h"

namespace tcsb {
namespace {

/// The most heap above `before` the pass held at any step of any track.
class HeapHighWater final : public WorldObserver {
 public:
  explicit HeapHighWater(std::size_t before) : before_(before) {}
  bool wants(const std::string&, int) const override { return true; }
  void observe(const WorldStepView&) override { most = std::max(most, testing::heap_in_use() - before_); }
  std::size_t most = 0;

 private:
  std::size_t before_;
};

TEST(WorldMemory, TheEstimateBoundsTheHeapOfTheWorldPass) {
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "AddressSanitizer's red zones and quarantine change the heap this test measures";
#endif
  nlohmann::json j = testing::world_suite_json();
  for (auto& net : j["nets"]) net["width"] = net["height"] = 33;
  j["fidelity"] = {{"curves", {{"budgets", {0.25}}, {"solver_divisors", {2, 4}}}}};
  j["steps"] = 20;
  const Suite suite = parse_suite_text(j.dump(), "row.json");
  const WorldTracks tracks = world_tracks(suite);
  EXPECT_EQ(tracks.tcsb, 4);   // tcsb_world and tcsb_body at 0.25 and 0.5
  EXPECT_EQ(tracks.plain, 6);  // full resolution, discrete LOD at both, the noise floor, two divisors
  const double estimate = static_cast<double>(estimate_peak_bytes(suite));
  HeapHighWater heap(testing::heap_in_use());
  const WorldResult result = run_world(suite, &heap);
  ASSERT_EQ(result.methods.size(), 10u);
  EXPECT_GE(estimate, static_cast<double>(heap.most)) << "the estimate is low";
  EXPECT_LE(estimate, 3.0 * static_cast<double>(heap.most)) << "the estimate is more than three times the heap";
}

TEST(WorldMemory, ALongerGeomorphCountsTheJumpsItHolds) {
  nlohmann::json j = testing::world_suite_json();
  const Suite blend = parse_suite_text(j.dump(), "row.json");
  j["fidelity"]["geomorph_boundaries"] = 240;
  const Suite longer = parse_suite_text(j.dump(), "long.json");
  const NetSpec& net = blend.nets.front();
  // A jump a boundary, each over every leaf at most: a leaf index and its offset.
  const double per_boundary = static_cast<double>(world_tracks(blend).tcsb) *
                              static_cast<double>(blend.scene.bodies.size()) * static_cast<double>(net.node_count()) *
                              (4 + 24);
  const double more = 240 - (blend.tcsb.blend_steps + 1);
  EXPECT_GE(static_cast<double>(estimate_peak_bytes(longer)),
            static_cast<double>(estimate_peak_bytes(blend)) + more * per_boundary - 1.0);
}

}  // namespace
}  // namespace tcsb
