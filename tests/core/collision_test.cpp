// Table-driven test of the FCL adapter (core/collision.h): box pairs and expected outcome.
#include "core/collision.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace mg {
namespace {

BoxPose car(double x, double y, double yaw = 0.0) { return {x, y, yaw, 4.0, 2.0, 1.5}; }

struct PairCase {
  std::string name;
  BoxPose a0, a1, b0, b1;
  bool collide;
  bool by_continuous;
};

TEST(CollisionAdapter, BoxPairTableGivesExpectedOutcome) {
  const double kPi = std::acos(-1.0);
  const std::vector<PairCase> table = {
      // 4 m long cars, bumpers 1 m apart: centres 5 m apart.
      {"apart_same_lane", car(0, 0), car(0, 0), car(5, 0), car(5, 0), false, false},
      // Adjacent lanes 3.5 m apart, widths 2: 1.5 m lateral clearance.
      {"apart_adjacent_lane", car(0, 0), car(0, 0), car(0, 3.5), car(0, 3.5), false, false},
      // Bumpers exactly touching (centres 4 m apart): contact counts as a collision.
      {"touching", car(0, 0), car(0, 0), car(4.0, 0), car(4.0, 0), true, false},
      {"overlapping", car(0, 0), car(0, 0), car(3, 0.5), car(3, 0.5), true, false},
      // b rotated 90 deg: its 4 m length spans y in [-2, 2], x in [4.0, 6.0]: 1 m from a's
      // front at x = 2 ... move it to x = 3.5 so its footprint x in [2.5, 4.5]: apart by 0.5.
      {"rotated_apart", car(0, 0), car(0, 0), car(3.5, 0, kPi / 2), car(3.5, 0, kPi / 2), false, false},
      // Rotated 45 deg at x = 3.2: its corner reaches x = 3.2 - (4 cos45 + 2 sin45)/2 = 1.08 < 2.
      {"rotated_overlapping", car(0, 0), car(0, 0), car(3.2, 0, kPi / 4), car(3.2, 0, kPi / 4), true, false},
      // Crossing at speed: b moves laterally 20 m between two steps straight through a
      // (y from -10 to +10); both end poses are far apart, only the continuous check sees it.
      {"crossing_between_steps", car(0, 0), car(0, 0), car(0, -10, kPi / 2), car(0, 10, kPi / 2), true, true},
      // Same motion 10 m further along X never touches.
      {"passing_behind", car(0, 0), car(0, 0), car(10, -10, kPi / 2), car(10, 10, kPi / 2), false, false},
      // Rear-end at 60 m/s relative speed in one 0.1 s step: 6 m, from 1 m gap to behind.
      {"rear_end_tunnel", car(0, 0), car(6.0, 0), car(5.0, 0), car(5.0, 0), true, false},
  };
  for (const auto& c : table) {
    const PairCheck r = check_box_pair(c.a0, c.a1, c.b0, c.b1);
    EXPECT_EQ(r.collide, c.collide) << c.name;
    EXPECT_EQ(r.by_continuous, c.by_continuous) << c.name;
    EXPECT_EQ(r.margin_m < 0.0, c.collide) << c.name << " margin " << r.margin_m;
  }
}

TEST(CollisionAdapter, MarginIsClearanceWhenApart) {
  // Same lane, centres 5 m apart, 4 m long: bumper gap 1 m.
  EXPECT_NEAR(check_box_pair(car(0, 0), car(0, 0), car(5, 0), car(5, 0)).margin_m, 1.0, 1e-9);
  // Adjacent lanes: 3.5 - 2 = 1.5 m.
  EXPECT_NEAR(check_box_pair(car(0, 0), car(0, 0), car(1, 3.5), car(1, 3.5)).margin_m, 1.5, 1e-9);
}

TEST(CollisionAdapter, PenetrationDepthIsNegativeMargin) {
  // Centres 3 m apart in the same lane: 1 m longitudinal overlap.
  const PairCheck r = check_box_pair(car(0, 0), car(0, 0), car(3, 0), car(3, 0));
  ASSERT_TRUE(r.collide);
  EXPECT_NEAR(r.margin_m, -1.0, 1e-6);
}

TEST(CollisionAdapter, ExactDistanceWhenOnlyBoundingRectanglesOverlap) {
  // b rotated 45 deg at (3.8, 2.8): its corners are (4.507, 4.921), (5.921, 3.507),
  // (1.679, 2.093), (3.093, 0.679), so its AABB starts at x = 1.679 < 2 and y = 0.679 < 1 and
  // overlaps a's AABB [-2, 2] x [-1, 1]. The near edge of b lies on x + y = 3.772 and a's corner
  // (2, 1) has x + y = 3: the boxes are apart by (3.772 - 3) / sqrt(2) = 0.546 m.
  const double kPi = std::acos(-1.0);
  const BoxPose b = car(3.8, 2.8, kPi / 4);
  ASSERT_LE(aabb_clearance_m(car(0, 0), b), 0.0);
  const ContactResult exact = fcl_box_contact(car(0, 0), b);
  ASSERT_FALSE(exact.collide);
  EXPECT_NEAR(exact.clearance_m, (3.8 + 2.8 - 2.0 * std::sqrt(2.0) - 3.0) / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(check_box_pair(car(0, 0), car(0, 0), b, b).margin_m, exact.clearance_m, 1e-12);
}

}  // namespace
}  // namespace mg
