// RCPP's path in the side lane (planner/side_lane_path.h): the return to the centre and the hold
// after a shallow abort.
#include "planner/side_lane_path.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "core/scenario.h"

namespace mg {
namespace {

// The default road, the ego offset_m toward the main lane from its side-lane centre at 13 m/s
// along the road, and the lateral state of a merge aborted there.
struct AbortedAt {
  Scenario s;
  WorldSnapshot w;
  SideLaneLateral lateral;
  explicit AbortedAt(double offset_m) {
    s.ego.y_m = s.road.side_lane_y_m() + offset_m;
    s.ego.speed_mps = 13.0;
    w = initial_snapshot(s);
    lateral = lateral_after_abort(w);
  }
};

// The ego 0.095 m off its side-lane centre toward the main lane, at 13 m/s along the road, its
// lateral speed spent: a merge aborted where it had stalled just short of the judge's start
// offset (0.1 m). The path holds that Y; a swing back to the centre would be a lateral-speed
// reversal the smoothness rule counts, with no start it credits (a campaign finding).
TEST(SideLanePath, AShallowAbortWithItsLateralMotionSpentHoldsTheLateralPosition) {
  AbortedAt a(0.095);
  const WorldSnapshot& w = a.w;
  SideLaneLateral& lateral = a.lateral;
  ASSERT_TRUE(lateral.hold_pending);
  const std::vector<PathPoint> path = side_lane_path(lateral, w);
  ASSERT_FALSE(path.empty());
  for (const PathPoint& p : path) EXPECT_DOUBLE_EQ(p.y_m, w.ego.y_m) << "x = " << p.x_m;
  ASSERT_TRUE(lateral.hold_y_m.has_value());
  EXPECT_DOUBLE_EQ(*lateral.hold_y_m, w.ego.y_m);
  // Kept on the next cycles.
  for (const PathPoint& p : side_lane_path(lateral, w)) EXPECT_DOUBLE_EQ(p.y_m, w.ego.y_m);
}

// Farther out (0.3 m) an abort returns to the centre: the path ends there.
TEST(SideLanePath, ADeeperAbortReturnsToTheCentre) {
  AbortedAt a(0.3);
  EXPECT_FALSE(a.lateral.hold_pending);
  const std::vector<PathPoint> path = side_lane_path(a.lateral, a.w);
  ASSERT_FALSE(path.empty());
  EXPECT_NEAR(path.back().y_m, a.s.road.side_lane_y_m(), 1e-9);
  EXPECT_LT(path.back().y_m, a.w.ego.y_m);
}

// The way back of a merge deferred for the weaving budget (past_centre_m) ends beyond the centre,
// and crosses the rules' merge_abort_offset_m above the centre, where the judge credits the
// return, on its steep part: a return ending on the centre crosses that line in its tail, where
// the tracker, lagging the path, arrived a decimetre short and covered the rest at a few cm/s.
TEST(SideLanePath, AWayBackPastTheCentreCrossesTheAbortOffsetOnItsSteepPart) {
  const auto slope_at_line = [](double past_centre_m) {
    AbortedAt a(0.6);
    a.lateral.past_centre_m = past_centre_m;
    const std::vector<PathPoint> path = side_lane_path(a.lateral, a.w);
    EXPECT_NEAR(path.back().y_m, a.s.road.side_lane_y_m() - past_centre_m, 1e-9);
    const ReturnPath& r = *a.lateral.return_path;
    const double line_y = a.s.road.side_lane_y_m() + a.s.params.rules.merge_abort_offset_m;
    double steepest = 0.0, at_line = 0.0;
    for (double x = r.x0_m; x < r.end_x_m(); x += 0.05) {
      const double slope = (r.y_at_m(x) - r.y_at_m(x + 0.05)) / 0.05;  // downward
      steepest = std::max(steepest, slope);
      if (at_line == 0.0 && r.y_at_m(x + 0.05) < line_y) at_line = slope;
    }
    return at_line / steepest;
  };
  const double to_centre = slope_at_line(0.0), past = slope_at_line(kDeferredReturnPastCentreM);
  EXPECT_GT(past, 1.5 * to_centre) << past << " against " << to_centre;
}

}  // namespace
}  // namespace mg
