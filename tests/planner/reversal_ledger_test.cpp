#include "planner/reversal_ledger.h"

#include <gtest/gtest.h>

#include "core/scenario.h"

namespace mg {
namespace {

// The ego of a default setup (lane width 3.5 m: side-lane centre Y = -3.5; the rule's defaults:
// start beyond Y = -3.4 moving out at more than 0.1 m/s, back at the centre below Y = -3.45, 2
// sign changes per approach), observed every 0.1 s while its lateral speed follows a script.
class ObservedEgo {
 public:
  ObservedEgo() { w_.setup = &setup_; }
  // Moves at vy_mps (road frame, heading along the road) for duration_s, observed every 0.1 s.
  void move(double vy_mps, double duration_s) {
    for (int i = 0; i < static_cast<int>(duration_s / 0.1 + 0.5); ++i) {
      w_.ego.vy_mps = vy_mps;
      ledger.observe(w_);
      w_.ego.y_m += vy_mps * 0.1;
      w_.time_s += 0.1;
    }
  }
  double y_m() const { return w_.ego.y_m; }
  ReversalLedger ledger;

 private:
  PlannerSetup setup_ = [] {
    PlannerSetup s;
    s.ego.speed_mps = 20.0;
    return s;
  }();
  WorldSnapshot w_ = [] {
    WorldSnapshot w;
    w.ego.y_m = -3.5;
    w.ego.vx_mps = 20.0;
    return w;
  }();
};

TEST(ReversalLedger, AMergeFromTheCentreIsAffordableAndEarnsAnApproach) {
  ObservedEgo e;
  EXPECT_TRUE(e.ledger.can_afford_merge());
  e.move(0.5, 1.0);  // out to Y = -3.0: a start
  EXPECT_EQ(e.ledger.approaches(), 1);
  EXPECT_EQ(e.ledger.changes(), 0);
}

// Out, back short of the centre, out again (the one start off the centre the rule credits), back
// short of the centre again: a third start would be off the centre and earn nothing, and its
// turn toward the lane and an abort would make 4 + ... sign changes against 4 allowed. Back at
// the centre, a start is a new approach again.
TEST(ReversalLedger, OnlyOneStartOffTheCentreIsAffordableUntilTheEgoIsBackThere) {
  ObservedEgo e;
  e.move(0.5, 1.0);   // Y -3.5 -> -3.0, start (approach 1)
  e.move(-0.5, 0.8);  // back to -3.4: change 1, not at the centre
  EXPECT_GT(e.y_m(), -3.45);
  EXPECT_TRUE(e.ledger.can_afford_merge());  // 1 + 2 <= 2 x 2 (the credited off-centre start)
  e.move(0.5, 0.8);   // out again: change 2, start off the centre (approach 2)
  EXPECT_EQ(e.ledger.approaches(), 2);
  e.move(-0.5, 0.8);  // back to -3.4 again: change 3
  EXPECT_EQ(e.ledger.changes(), 3);
  EXPECT_FALSE(e.ledger.can_afford_merge());  // 3 + 2 > 2 x 2: nothing more is credited off the centre
  EXPECT_EQ(e.ledger.allowed_with_merge(), 4);
  e.move(-0.5, 0.3);  // observed at -3.4, -3.45 and -3.5: back at the centre
  EXPECT_TRUE(e.ledger.can_afford_merge());   // 3 + 2 <= 2 x 3
  EXPECT_EQ(e.ledger.allowed_with_merge(), 6);
}

TEST(ReversalLedger, AMergeTurningBackTowardTheLaneCostsAChangeAnAbortAnother) {
  // One approach (2 allowed), its attempt still under way: moving out, one abort is affordable
  // (0 + 0 + 1); after a ripple back and out again (2 changes, too small to be an abort) the
  // next abort is not.
  ObservedEgo e;
  e.move(0.5, 1.0);
  EXPECT_TRUE(e.ledger.can_afford_merge());
  e.move(-0.3, 0.1);  // 0.03 m back: a sign change, no abort (merge_abort_reversal_m is 0.05 m)
  e.move(0.5, 0.5);
  EXPECT_EQ(e.ledger.changes(), 2);
  EXPECT_EQ(e.ledger.approaches(), 1);
  EXPECT_FALSE(e.ledger.can_afford_merge());
}

TEST(ReversalLedger, AMergeWhosePathFirstTurnsAwayCostsTwoChangesMoreForAnEgoMovingOut) {
  // One approach, moving out, no change yet: a merge along a path above the ego costs its abort
  // alone (1 <= 2); one whose path lies below the ego turns it away, back toward the lane, and
  // back again should it abort (3 > 2). Moving back already, the turn away costs nothing.
  ObservedEgo e;
  e.move(0.5, 1.0);
  EXPECT_TRUE(e.ledger.last_moved_out());
  EXPECT_TRUE(e.ledger.can_afford_merge(false));
  EXPECT_FALSE(e.ledger.can_afford_merge(true));
  e.move(-0.5, 0.4);  // back 0.2 m: change 1, an abort by reversal, not at the centre
  EXPECT_FALSE(e.ledger.last_moved_out());
  EXPECT_TRUE(e.ledger.can_afford_merge(true));  // 1 + 0 + 1 + 1 <= 2 x 2 (the credited off-centre start)
}

TEST(ReversalLedger, LateralMotionBeforeTheFirstStartIsNotCounted) {
  // Centring wobble in the side lane, below the start offset: the rule counts from the first start.
  ObservedEgo e;
  e.move(0.3, 0.2);
  e.move(-0.3, 0.2);
  e.move(0.3, 0.2);
  EXPECT_EQ(e.ledger.changes(), 0);
  EXPECT_EQ(e.ledger.approaches(), 0);
  EXPECT_TRUE(e.ledger.can_afford_merge());
}

}  // namespace
}  // namespace mg
