#include "core/collision.h"

#include <algorithm>
#include <cmath>

#include <fcl/geometry/shape/box.h>
#include <fcl/math/motion/interp_motion.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/narrowphase/distance.h>

namespace mg {
namespace {

fcl::Transform3d transform_of(const BoxPose& p) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = fcl::AngleAxisd(p.yaw_rad, fcl::Vector3d::UnitZ()).toRotationMatrix();
  tf.translation() = fcl::Vector3d(p.x_m, p.y_m, 0.5 * p.height_m);
  return tf;
}

fcl::Boxd box_of(const BoxPose& p) { return fcl::Boxd(p.length_m, p.width_m, p.height_m); }

}  // namespace

Footprint footprint_of(const BoxPose& p) {
  double hx = 0.5 * p.length_m, hy = 0.5 * p.width_m;
  if (p.yaw_rad != 0.0) {
    const double c = std::abs(std::cos(p.yaw_rad));
    const double s = std::abs(std::sin(p.yaw_rad));
    hx = 0.5 * (p.length_m * c + p.width_m * s);
    hy = 0.5 * (p.length_m * s + p.width_m * c);
  }
  return {p.x_m - hx, p.x_m + hx, p.y_m - hy, p.y_m + hy};
}

Footprint unite(const Footprint& a, const Footprint& b) {
  return {std::min(a.x_lo, b.x_lo), std::max(a.x_hi, b.x_hi), std::min(a.y_lo, b.y_lo), std::max(a.y_hi, b.y_hi)};
}

double clearance_m(const Footprint& a, const Footprint& b) {
  return std::max(std::max(a.x_lo - b.x_hi, b.x_lo - a.x_hi), std::max(a.y_lo - b.y_hi, b.y_lo - a.y_hi));
}

double aabb_clearance_m(const BoxPose& a, const BoxPose& b) {
  return clearance_m(footprint_of(a), footprint_of(b));
}

double swept_aabb_clearance_m(const BoxPose& a0, const BoxPose& a1, const BoxPose& b0,
                              const BoxPose& b1) {
  return clearance_m(unite(footprint_of(a0), footprint_of(a1)), unite(footprint_of(b0), footprint_of(b1)));
}

ContactResult fcl_box_contact(const BoxPose& a, const BoxPose& b) {
  const fcl::Boxd ga = box_of(a);
  const fcl::Boxd gb = box_of(b);
  const fcl::Transform3d ta = transform_of(a);
  const fcl::Transform3d tb = transform_of(b);
  fcl::CollisionRequestd request(1, /*enable_contact=*/true);
  fcl::CollisionResultd result;
  fcl::collide(&ga, ta, &gb, tb, request, result);
  ContactResult out;
  if (result.isCollision()) {
    out.collide = true;
    out.penetration_m = result.numContacts() > 0 ? std::max(result.getContact(0).penetration_depth, 0.0) : 0.0;
    return out;
  }
  fcl::DistanceRequestd drequest;
  fcl::DistanceResultd dresult;
  out.clearance_m = std::max(fcl::distance(&ga, ta, &gb, tb, drequest, dresult), 0.0);
  return out;
}

std::optional<double> fcl_box_contact_continuous(const BoxPose& a0, const BoxPose& a1,
                                                 const BoxPose& b0, const BoxPose& b1) {
  const double rel_dx = (a1.x_m - a0.x_m) - (b1.x_m - b0.x_m);
  const double rel_dy = (a1.y_m - a0.y_m) - (b1.y_m - b0.y_m);
  const double smallest = std::min({a0.length_m, a0.width_m, b0.length_m, b0.width_m});
  // Rotation sweeps the corners too: bound their displacement by half-diagonal * |d yaw|.
  const double turn = std::max(std::abs(a1.yaw_rad - a0.yaw_rad) * std::hypot(a0.length_m, a0.width_m),
                               std::abs(b1.yaw_rad - b0.yaw_rad) * std::hypot(b0.length_m, b0.width_m));
  const double travel = std::hypot(rel_dx, rel_dy) + turn;
  const std::size_t samples =
      static_cast<std::size_t>(std::ceil(travel / (0.5 * smallest))) + 2;
  const fcl::Boxd ga = box_of(a0);
  const fcl::Boxd gb = box_of(b0);
  const fcl::InterpMotion<double> motion_a(transform_of(a0), transform_of(a1));
  const fcl::InterpMotion<double> motion_b(transform_of(b0), transform_of(b1));
  fcl::ContinuousCollisionRequestd request(samples, 1.0 / static_cast<double>(samples), fcl::CCDM_LINEAR,
                                           fcl::GST_LIBCCD, fcl::CCDC_NAIVE);
  fcl::ContinuousCollisionResultd result;
  fcl::continuousCollide(&ga, &motion_a, &gb, &motion_b, request, result);
  if (!result.is_collide) return std::nullopt;
  return result.time_of_contact;
}

PairCheck check_box_pair(const BoxPose& a0, const BoxPose& a1, const BoxPose& b0, const BoxPose& b1) {
  if (swept_aabb_clearance_m(a0, a1, b0, b1) > 0.0) {  // pre-filter: cannot touch
    PairCheck out;
    out.margin_m = aabb_clearance_m(a1, b1);
    return out;
  }
  return check_box_pair_fcl(a0, a1, b0, b1, aabb_clearance_m(a1, b1));
}

PairCheck check_box_pair_fcl(const BoxPose& a0, const BoxPose& a1, const BoxPose& b0, const BoxPose& b1,
                             double now) {
  PairCheck out;
  const ContactResult at_step = fcl_box_contact(a1, b1);
  if (at_step.collide) {
    out.collide = true;
    out.margin_m = -std::max(at_step.penetration_m, 1e-6);  // touching is contact: never >= 0
    return out;
  }
  out.margin_m = now > 0.0 ? now : at_step.clearance_m;
  if (auto toc = fcl_box_contact_continuous(a0, a1, b0, b1)) {
    out.collide = true;
    out.by_continuous = true;
    out.contact_fraction = *toc;
    auto lerp = [f = *toc](const BoxPose& p0, const BoxPose& p1) {
      BoxPose p = p1;
      p.x_m = p0.x_m + f * (p1.x_m - p0.x_m);
      p.y_m = p0.y_m + f * (p1.y_m - p0.y_m);
      p.yaw_rad = p0.yaw_rad + f * (p1.yaw_rad - p0.yaw_rad);
      return p;
    };
    const ContactResult at_contact = fcl_box_contact(lerp(a0, a1), lerp(b0, b1));
    out.margin_m = -std::max(at_contact.penetration_m, 1e-6);  // a contact is never a margin >= 0
  }
  return out;
}

}  // namespace mg
