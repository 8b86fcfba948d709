// Figure frames (the paper's Figure 6 as data): without compression TC-SB's reconstructed surface is plain Bullet's,
// exactly; under a budget the frames show fewer nodes and mark exactly the links of the operations in flight; the
// requested steps are checked.
#include "fidelity/figure_frames.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace tcsb {
namespace {

Suite one_net_suite() {
  Suite s;
  s.name = std::string("frames");  // moved in: GCC 12 -Wrestrict false positive on literal assignment
  NetSpec n;
  n.name = std::string("n17");
  n.width = n.height = 17;
  s.nets = {n};
  s.methods = {Method::kPlain, Method::kTcsb};
  s.compression = {1.0, 0.5};
  s.feedback.max_ops_per_step = 16;
  return s;
}

TEST(FigureFrames, WithoutCompressionTheSurfaceIsPlainBulletExactly) {
  const FigureFrames f = record_figure_frames(one_net_suite(), 0, 1.0, {0, 10, 40});
  EXPECT_EQ(f.net, "n17");
  EXPECT_EQ(f.extent, one_net_suite().nets[0].size_x);  // a square net: its side
  EXPECT_FALSE(f.diverged_step);
  ASSERT_EQ(f.frames.size(), 3u);
  for (const FigureFrame& frame : f.frames) {
    ASSERT_EQ(frame.plain.size(), 289u) << "step " << frame.step;
    EXPECT_EQ(frame.tcsb_surface, frame.plain) << "step " << frame.step;
    EXPECT_EQ(frame.tcsb_nodes.size(), 289u);
    EXPECT_EQ(frame.interpolations, 0);
    for (const FrameLink& l : frame.tcsb_links) EXPECT_EQ(l.role, LinkRole::kSteady);
  }
  EXPECT_NE(f.frames[0].plain, f.frames[2].plain);  // the net fell in between
}

TEST(FigureFrames, UnderABudgetTheLinksBeingReplacedAreThoseOfOperationsInFlight) {
  const FigureFrames f = record_figure_frames(one_net_suite(), 0, 0.5, {1, 2, 3, 40});
  ASSERT_EQ(f.frames.size(), 4u);
  bool blending_seen = false;
  for (const FigureFrame& frame : f.frames) {
    const int n = static_cast<int>(frame.tcsb_nodes.size());
    EXPECT_EQ(frame.tcsb_surface.size(), 289u);
    bool replaced = false;
    for (const FrameLink& l : frame.tcsb_links) {
      ASSERT_TRUE(l.a >= 0 && l.a < n && l.b >= 0 && l.b < n) << "step " << frame.step;
      replaced = replaced || l.role != LinkRole::kSteady;
    }
    EXPECT_EQ(replaced, frame.interpolations > 0) << "step " << frame.step;
    blending_seen = blending_seen || replaced;
  }
  EXPECT_TRUE(blending_seen);  // the budget makes TC-SB coarsen from the first steps
  EXPECT_LT(f.frames.back().tcsb_nodes.size(), 289u);
}

TEST(FigureFrames, StepsMustIncrease) {
  EXPECT_THROW(record_figure_frames(one_net_suite(), 0, 0.5, {3, 3}), std::invalid_argument);
  EXPECT_THROW(record_figure_frames(one_net_suite(), 0, 0.5, {-1}), std::invalid_argument);
  EXPECT_THROW(record_figure_frames(one_net_suite(), 1, 0.5, {1}), std::invalid_argument);
  EXPECT_TRUE(record_figure_frames(one_net_suite(), 0, 0.5, {}).frames.empty());
}

}  // namespace
}  // namespace tcsb
