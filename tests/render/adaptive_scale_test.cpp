// The adaptive resolution's controller (render/adaptive_scale.h), without GL: from the frames'
// costs, which scale the next frame is drawn at, and how long after the last move it stays there.
#include <gtest/gtest.h>

#include "render/adaptive_scale.h"

namespace ps {
namespace {

// A full redraw at `scale` costing `ms`, the view moving, at time `t_ms`.
void moving_frame(AdaptiveScale& a, double t_ms, double ms, double scale = 1.0) { a.frame(t_ms, ms, scale, true, true); }

TEST(AdaptiveScaleTest, NothingMeasuredDrawsWhole) {
  const AdaptiveScale a;
  EXPECT_EQ(a.next(0.0), (SurfaceScale{1.0, 1.0}));
  EXPECT_EQ(a.full_cost_ms(), 0.0);
}

// docs/benchmarks.md's full redraws on 2-core llvmpipe: 38.4 ms at 1280x720 (0.75^2 * 38.4 =
// 21.6 ms is over the 16.7 ms budget, 0.5^2 * 38.4 = 9.6 ms fits) and 85.8 ms at 1920x1080
// (0.5^2 * 85.8 = 21.5 ms over, 0.35^2 * 85.8 = 10.5 ms fits).
TEST(AdaptiveScaleTest, TheLargestStepWhoseCostFitsTheBudget) {
  const struct {
    double full_ms, scale;
  } cases[] = {{10.0, 1.0}, {16.7, 1.0}, {20.0, 0.75}, {29.0, 0.75}, {38.4, 0.5}, {85.8, 0.35}, {500.0, 0.35}};
  for (const auto& c : cases) {
    AdaptiveScale a;
    moving_frame(a, 0.0, c.full_ms);
    EXPECT_EQ(a.next(1.0).moving, c.scale) << c.full_ms << " ms";
  }
}

TEST(AdaptiveScaleTest, AReducedFrameCountsAsItsPixels) {
  AdaptiveScale a;
  moving_frame(a, 0.0, 14.0, 0.5);  // 14 ms at a quarter of the pixels: 56 ms whole
  EXPECT_DOUBLE_EQ(a.full_cost_ms(), 56.0);
  // 0.75 would cost 31.5 ms by pixels; 0.5's own 14 ms fits with too little room to try it.
  EXPECT_EQ(a.next(1.0).moving, 0.5);
}

// bench --moving's Field travel (docs/benchmarks.md): as the view leaves the scene a whole frame
// falls to 9 ms, while the 0.35 frame, with its upsample and full-resolution rectangle, stays
// near 10 ms; scaled by pixels the 10 ms says 82 ms whole and the view would stay at 0.35. A step
// whose own cost leaves room tries the whole frame, which then stays.
TEST(AdaptiveScaleTest, ACheapViewTriesTheWholeFrameAndStays) {
  AdaptiveScale a;
  for (int i = 0; i < 5; ++i) moving_frame(a, i * 10.0, 10.0, 0.35);
  EXPECT_NEAR(a.full_cost_ms(), 81.6, 0.1);
  EXPECT_EQ(a.next(50.0).moving, 1.0);  // 10 ms <= 0.8 x 16.7: whole is tried
  moving_frame(a, 50.0, 9.0, 1.0);
  for (double t = 60.0; t < 3000.0; t += 10.0) {
    ASSERT_EQ(a.next(t).moving, 1.0) << t << " ms";  // measured at 9 ms: stays
    moving_frame(a, t, 9.0, 1.0);
  }
}

// A whole frame tried and missed: the step above is tried next, and climbing goes on while a step
// leaves room; what missed is not tried again until its measurement is older than memory_ms.
TEST(AdaptiveScaleTest, AMissedWholeTryClimbsStepByStep) {
  AdaptiveScale a;
  for (int i = 0; i < 5; ++i) moving_frame(a, i * 10.0, 10.0, 0.35);
  ASSERT_EQ(a.next(50.0).moving, 1.0);
  moving_frame(a, 50.0, 30.0, 1.0);  // the whole frame: over the budget
  EXPECT_EQ(a.next(80.0).moving, 0.5);  // 0.35 still has room: the step above
  moving_frame(a, 80.0, 11.0, 0.5);
  EXPECT_EQ(a.next(91.0).moving, 0.75);
  moving_frame(a, 91.0, 15.0, 0.75);  // fits, without room: stays
  EXPECT_EQ(a.next(106.0).moving, 0.75);
  moving_frame(a, 106.0, 15.0, 0.75);
  EXPECT_EQ(a.next(121.0).moving, 0.75);
}

// Tries that miss go back down at once and wait memory_ms: one slow frame per second at most.
TEST(AdaptiveScaleTest, AMissedTryWaitsMemoryMs) {
  AdaptiveScale a;
  for (int i = 0; i < 5; ++i) moving_frame(a, i * 10.0, 12.0, 0.35);
  EXPECT_EQ(a.next(50.0).moving, 1.0);
  moving_frame(a, 50.0, 40.0, 1.0);  // over the budget
  EXPECT_EQ(a.next(90.0).moving, 0.5);
  moving_frame(a, 90.0, 25.0, 0.5);  // over the budget
  double t = 115.0;
  for (; t < 1050.0; t += 12.0) {
    ASSERT_EQ(a.next(t).moving, 0.35) << t << " ms";
    moving_frame(a, t, 12.0, 0.35);
  }
  EXPECT_EQ(a.next(t).moving, 1.0);  // the whole frame's 40 ms is more than a second old: tried again
  // With no room (0.35 at 14 ms > 0.8 x 16.7) nothing is tried.
  AdaptiveScale b;
  for (int i = 0; i < 5; ++i) moving_frame(b, i * 15.0, 14.0, 0.35);
  EXPECT_EQ(b.next(75.0).moving, 0.35);
  EXPECT_EQ(b.next(5000.0).moving, 0.35);
}

// An incremental frame (only the probe's rectangles redrawn) says nothing of a whole one's cost.
TEST(AdaptiveScaleTest, IncrementalFramesAreNotCosts) {
  AdaptiveScale a;
  moving_frame(a, 0.0, 38.4);
  for (int i = 1; i <= 10; ++i) a.frame(i * 4.0, 3.7, 1.0, false, false);
  EXPECT_DOUBLE_EQ(a.full_cost_ms(), 38.4);
}

// The median of the last five: one frame slowed by something else does not move the scale, a
// lasting change does within three frames.
TEST(AdaptiveScaleTest, OneSlowFrameDoesNotMoveTheScale) {
  AdaptiveScale a;
  for (int i = 0; i < 5; ++i) moving_frame(a, i * 16.0, 20.0);
  EXPECT_EQ(a.next(80.0).moving, 0.75);
  moving_frame(a, 80.0, 200.0);
  EXPECT_EQ(a.next(280.0).moving, 0.75);
  moving_frame(a, 280.0, 200.0);
  moving_frame(a, 480.0, 200.0);
  EXPECT_EQ(a.next(680.0).moving, 0.35);
}

// Still frames stay reduced for rest_ms after the last move (a drag's events do not come every
// frame), then are whole: well within the 100 ms the rest frame must come in.
TEST(AdaptiveScaleTest, WholeAgainAfterRestMs) {
  AdaptiveScale a;
  moving_frame(a, 100.0, 38.4);
  EXPECT_EQ(a.next(120.0), (SurfaceScale{0.5, 0.5}));
  EXPECT_EQ(a.next(130.0), (SurfaceScale{0.5, 0.5}));
  EXPECT_EQ(a.next(130.1), (SurfaceScale{0.5, 1.0}));
  EXPECT_LT(a.params().rest_ms, 100.0);
}

TEST(AdaptiveScaleTest, TheBudgetIsAParameter) {
  AdaptiveScaleParams p;
  p.budget_ms = 40.0;
  AdaptiveScale a(p);
  moving_frame(a, 0.0, 38.4);
  EXPECT_EQ(a.next(1.0).moving, 1.0);
}

}  // namespace
}  // namespace ps
