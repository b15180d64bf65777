// THE one FCL adapter of mergeguard (spec §8 collision freedom): a box per vehicle from its
// length, width and height at its planar pose; a discrete check at a step and a continuous
// check over the motion between two steps, both behind a cheap axis-aligned pre-filter so
// that FCL only runs for pairs that could touch. Every FCL object lives inside one call
// (FCL writes into shared geometry), so these functions are safe to call from many threads.
#pragma once

#include <optional>

namespace mg {

struct BoxPose {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
  double length_m = 0.0;
  double width_m = 0.0;
  double height_m = 0.0;
};

// Axis-aligned bounding rectangle of a box's footprint (no trigonometry when yaw == 0).
struct Footprint {
  double x_lo = 0.0, x_hi = 0.0, y_lo = 0.0, y_hi = 0.0;
};
Footprint footprint_of(const BoxPose& p);
Footprint unite(const Footprint& a, const Footprint& b);
// > 0 apart (the larger of the X and Y separations), <= 0 when the rectangles overlap.
double clearance_m(const Footprint& a, const Footprint& b);

// Signed clearance between the axis-aligned bounding rectangles of two footprints: > 0 apart
// (the larger of the X and Y separations), <= 0 when the rectangles overlap. A lower bound of
// the true clearance's sign: boxes can only touch when this is <= 0.
double aabb_clearance_m(const BoxPose& a, const BoxPose& b);
// The same for the rectangles swept by each box between two poses (union of both rectangles).
double swept_aabb_clearance_m(const BoxPose& a0, const BoxPose& a1, const BoxPose& b0,
                              const BoxPose& b1);

struct ContactResult {
  bool collide = false;
  double penetration_m = 0.0;     // > 0 when colliding (FCL contact depth)
  double clearance_m = 0.0;       // >= 0 when apart (exact FCL distance)
};
// Discrete FCL box-box check at one pose pair (exact, no pre-filter).
ContactResult fcl_box_contact(const BoxPose& a, const BoxPose& b);

// Continuous FCL check over the linear interpolation of both poses from *0 to *1. Returns the
// fraction in [0, 1] of the first contact, or nullopt. The number of FCL samples is chosen so
// that the relative displacement between samples is at most half the smaller box dimension:
// a box cannot pass through another between two samples.
std::optional<double> fcl_box_contact_continuous(const BoxPose& a0, const BoxPose& a1,
                                                 const BoxPose& b0, const BoxPose& b1);

struct PairCheck {
  bool collide = false;
  double margin_m = 0.0;          // AABB clearance when apart, 0 when only AABBs overlap,
                                  // -penetration on contact
  bool by_continuous = false;     // contact found only between the two steps
  double contact_fraction = 1.0;  // where between the steps (1 = at the second step)
};
// Pre-filtered pair check for the motion from step i-1 (a0, b0) to step i (a1, b1).
PairCheck check_box_pair(const BoxPose& a0, const BoxPose& a1, const BoxPose& b0, const BoxPose& b1);
// The FCL part of check_box_pair, for a pair whose swept rectangles overlap; `aabb_now` is
// clearance_m of the rectangles at step i.
PairCheck check_box_pair_fcl(const BoxPose& a0, const BoxPose& a1, const BoxPose& b0, const BoxPose& b1,
                             double aabb_now);

}  // namespace mg
