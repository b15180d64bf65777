#include "planner/merge_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/demand.h"
#include "core/rss.h"
#include "planner/rcpp_params.h"

namespace mg {

double ln_ratio(double fraction) { return std::log(fraction / (1.0 - fraction)); }
double half_span_times_kappa() { return ln_ratio(1.0 - kSigmoidEndFraction); }

double side_lane_exit_fraction(double ego_width_m, double lane_width_m) {
  return std::clamp(0.5 + ego_width_m / (2.0 * lane_width_m), 0.5 + 1e-3, 1.0 - kSigmoidEndFraction);
}

double side_exit_limit_x_m(const PlannerSetup& s, double speed_mps) {
  return s.road.side_lane_end_x_m - 0.5 * s.ego.size.length_m - std::max(kSideExitMarginM, kSideExitLagS * speed_mps);
}

double path_curvature_cap_per_m(const PlannerSetup& s) {
  const EgoDynamics& dyn = s.ego.dynamics;
  return std::min(std::tan(dyn.steer_max_rad) / (2.0 * dyn.wheelbase_m()), std::tan(kPathSideslipMaxRad) / dyn.cg_to_rear_m);
}

double crawl_speed_mps(const PlannerSetup& s) { return kCrawlSpeedFraction * s.params.rules.sideslip_min_speed_mps; }

double merge_curvature_cap_per_m(const PlannerSetup& s) {
  const EgoDynamics& dyn = s.ego.dynamics;
  return std::max(path_curvature_cap_per_m(s), std::min(std::tan(dyn.steer_max_rad) / (2.0 * dyn.wheelbase_m()),
                                                        std::tan(kPathTrackerSideslipRad) / dyn.cg_to_rear_m));
}

double path_curvature_cap_per_m(const PlannerSetup& s, double top_speed_mps) {
  if (top_speed_mps > crawl_speed_mps(s)) return path_curvature_cap_per_m(s);
  const EgoDynamics& dyn = s.ego.dynamics;
  return std::tan(dyn.steer_max_rad) / (2.0 * dyn.wheelbase_m());
}

double steady_sideslip_per_curvature_m(const EgoDynamics& d, double speed_mps) {
  return d.cg_to_rear_m - d.mass_kg * d.cg_to_front_m * speed_mps * speed_mps / (d.cornering_rear_npr * d.wheelbase_m());
}

namespace {

// The steepest sigmoid whose peak curvature, W kappa^2 / (6 sqrt 3), stays within curvature_per_m,
// and within the configured kappa_max.
double kappa_within_curvature_per_m(const PlannerSetup& s, double curvature_per_m) {
  return std::min(rcpp_params(s).kappa_max_per_m, std::sqrt(6.0 * std::sqrt(3.0) * curvature_per_m / s.road.lane_width_m));
}

}  // namespace

double kappa_cap_per_m(const PlannerSetup& s) { return kappa_within_curvature_per_m(s, path_curvature_cap_per_m(s)); }

double kappa_cap_per_m(const PlannerSetup& s, double top_speed_mps) {
  return kappa_within_curvature_per_m(s, path_curvature_cap_per_m(s, top_speed_mps));
}

double kappa_cap_per_m(const PlannerSetup& s, const SpeedRamp& ramp) {
  return kappa_cap_per_m(s, std::sqrt(ramp.top_speed_squared_m2ps2()));
}

double kappa_sharpest_per_m(const PlannerSetup& s, double top_speed_mps) {
  return std::max(kappa_cap_per_m(s, top_speed_mps), kappa_within_curvature_per_m(s, merge_curvature_cap_per_m(s)));
}

KappaRange kappa_range_for(const PlannerSetup& s, double pc_m, double start_x_m, double complete_by_x_m,
                           const SpeedRamp& ramp, double ramp_origin_x_m, double kappa_floor_per_m,
                           double start_fraction) {
  const RcppParams p = rcpp_params(s);
  const double before_m = pc_m - start_x_m;
  const double after_m = complete_by_x_m - pc_m;
  const double exit_room_m = side_exit_limit_x_m(s, std::max(ramp.v0_mps, ramp.v_target_mps)) - pc_m;
  if (before_m <= 0.0 || after_m <= 0.0 || exit_room_m <= 0.0) return std::nullopt;
  const double exit_fraction = side_lane_exit_fraction(s.ego.size.width_m, s.road.lane_width_m);
  const double floor_per_m = kappa_floor_per_m > 0.0 ? kappa_floor_per_m : p.kappa_min_per_m;
  const auto lowest_for = [&](double start_span_times_kappa) {
    return std::max({floor_per_m, start_span_times_kappa / before_m, half_span_times_kappa() / after_m,
                     ln_ratio(exit_fraction) / exit_room_m});
  };
  double lo = lowest_for(half_span_times_kappa());
  double kappa_cap = kappa_cap_per_m(s, ramp);
  // From a crawl, the start at the ego's own progress, but only under the cap: a sharper path is
  // tracked behind it, and one begun 18 % across the lane put a corner past the road's edge at
  // the side lane's end (`on_road`; a campaign finding).
  const double crawl_mps = crawl_speed_mps(s);
  const double top_mps = std::sqrt(ramp.top_speed_squared_m2ps2());
  if (ramp.v0_mps <= crawl_mps && top_mps > crawl_mps && lo > kappa_cap) {
    const double own_lo = lowest_for(ln_ratio(1.0 - std::clamp(start_fraction, kSigmoidEndFraction, 0.5)));
    if (own_lo <= kappa_cap) lo = own_lo;
  }
  if (lo > kappa_cap) kappa_cap = kappa_sharpest_per_m(s, top_mps);
  if (lo > kappa_cap) return std::nullopt;
  // The search needs the margin's sign only: a flat sigmoid is comfortable by the bound alone (a
  // lower bound of the margin, then >= 0), without the speed profile.
  const auto comfort_margin = [&](double kappa) {
    const Sigmoid sig{s.road.lane_width_m, kappa, pc_m, -s.road.lane_width_m};
    const double by_bound = p.lat_accel_comfort_mps2 - peak_lat_accel_bound_mps2(sig, ramp);
    if (by_bound >= 0.0) return by_bound;
    return p.lat_accel_comfort_mps2 - peak_lat_accel_along_mps2(sig, ramp, ramp_origin_x_m);
  };
  const auto hi = highest_satisfying(comfort_margin, lo, kappa_cap, 1e-5);
  if (!hi) return std::nullopt;
  return std::make_pair(lo, *hi);
}

double Track::x_at(double t_s) const {
  const double own_m = x0_m + motion.distance_at_m(t_s);
  return behind.active ? std::min(own_m, behind.x_at(t_s)) : own_m;
}

double Track::v_at(double t_s) const {
  const double own_mps = motion.speed_at_mps(t_s);
  if (!behind.active || x0_m + motion.distance_at_m(t_s) < behind.x_at(t_s)) return own_mps;
  return std::min(own_mps, behind.motion.speed_at_mps(t_s));
}

Track follower_track(const MainLaneVehicle& f, double rho_s, double observed_accel_mps2) {
  const double a = std::max(f.limits.accel_max_mps2, observed_accel_mps2);
  return Track{f.x_m, SpeedRamp{f.speed_mps, f.speed_mps + a * 0.5 * rho_s, a, a}, f.length_m, f.width_m, f.limits, 0.0, {}};
}

Track behind_follower_track(const MainLaneVehicle& v, const MainLaneVehicle& follower, double rho_s,
                            double observed_accel_mps2, double follower_accel_mps2) {
  Track t = follower_track(v, rho_s, observed_accel_mps2);
  const Track ahead = follower_track(follower, rho_s, follower_accel_mps2);
  t.behind = BehindBound{true, ahead.x0_m, ahead.motion, 0.5 * (v.length_m + follower.length_m) + kLeaderStandoffM};
  return t;
}

const MainLaneVehicle* next_in_lane(const std::vector<MainLaneVehicle>& lane, const MainLaneVehicle& v) {
  const MainLaneVehicle* next = nullptr;
  for (const MainLaneVehicle& u : lane)
    if (lane_order_before(v, u) && (next == nullptr || lane_order_before(u, *next))) next = &u;
  return next;
}

namespace {

// LeaderHorizon: whether `l` at its speed is still D_lon, and kLeaderStandoffM, behind `ahead`
// (braking at ahead_braking_mps2 to a stop) at h.horizon_s. The distance between them is concave
// in time (`ahead`'s travel is, `l`'s is linear), so it is smallest now or at the horizon: the
// horizon is the one instant to check, `l` being clear now (bumpers_m, braking_behind_mps2).
// Written as "clear" so that a NaN predicts the braking.
bool holds_speed_behind(const MainLaneVehicle& l, const MainLaneVehicle& ahead, double ahead_braking_mps2,
                        double bumpers_m, const LeaderHorizon& h) {
  if (!std::isfinite(h.horizon_s)) return false;
  const SpeedRamp ahead_motion{ahead.speed_mps, ahead_braking_mps2 > 0.0 ? 0.0 : ahead.speed_mps, 1.0,
                               std::max(ahead_braking_mps2, 1e-9)};
  const double gap_at_horizon_m =
      ahead.x_m + ahead_motion.distance_at_m(h.horizon_s) - (l.x_m + l.speed_mps * h.horizon_s);
  // RCPP eq. (1) with the speeds of now, as the progress rule's leader_holds_speed takes them.
  const double d_lon_m = rss_longitudinal_m({std::max(l.speed_mps, 0.0), std::max(ahead.speed_mps, 0.0), l.length_m,
                                             ahead.length_m, h.response_time_s, l.limits.accel_max_mps2,
                                             l.limits.brake_min_mps2, ahead.limits.brake_max_mps2});
  return gap_at_horizon_m >= std::max(d_lon_m, bumpers_m);
}

}  // namespace

double braking_behind_mps2(const MainLaneVehicle& l, const MainLaneVehicle& ahead, double ahead_accel_mps2,
                           const LeaderHorizon& h) {
  const double bumpers_m = 0.5 * (l.length_m + ahead.length_m) + kLeaderStandoffM;
  const double gap_m = ahead.x_m - l.x_m - bumpers_m;
  const double ahead_braking_mps2 = ahead_accel_mps2 < -kLeaderBrakingMps2 ? -ahead_accel_mps2 : 0.0;
  const double closing_mps = l.speed_mps - ahead.speed_mps;
  // Inside the standoff already: no braking keeps it, unless the gap does not shrink (a driver
  // following at a shorter distance than kLeaderStandoffM at the same speed is not braking, and
  // one predicted so, at 1e3 m/s2, predicted every vehicle behind it stopping at once: it closed
  // a gap two vehicles back for seconds while `progress` offered it; a campaign finding).
  if (gap_m <= 0.0) return closing_mps <= 0.0 && ahead_braking_mps2 == 0.0 ? 0.0 : 1e3;
  if (holds_speed_behind(l, ahead, ahead_braking_mps2, bumpers_m, h)) return 0.0;
  // Uniform braking b behind `ahead` (at constant speed, or braking uniformly to a stop): while
  // both move the gap is smallest where the speeds match, at gap - closing^2 / (2 (b - b_a)), so
  // b >= b_a + closing^2 / (2 gap) whenever that match comes before `ahead` stops.
  const auto match_bound_mps2 = [&] { return ahead_braking_mps2 + closing_mps * closing_mps / (2.0 * gap_m); };
  if (ahead_braking_mps2 == 0.0) return closing_mps > 0.0 ? std::min(1e3, match_bound_mps2()) : 0.0;
  // Both come to rest: b stops `l` behind where `ahead` stops. If at that b the speeds still
  // match while `ahead` moves, the match bound is the larger one; otherwise the gap only shrinks
  // until `l` stops, and that stop is the binding one. (Taking the match bound regardless asked a
  // vehicle behind one crawling to a stop, seen braking hard for an instant, to brake as hard.)
  const double room_m = gap_m + ahead.speed_mps * ahead.speed_mps / (2.0 * ahead_braking_mps2);
  const double stop_mps2 = l.speed_mps * l.speed_mps / (2.0 * room_m);
  if (closing_mps > 0.0 && stop_mps2 > ahead_braking_mps2 &&
      closing_mps * ahead_braking_mps2 < ahead.speed_mps * (stop_mps2 - ahead_braking_mps2) &&
      2.0 * gap_m * (stop_mps2 - ahead_braking_mps2) < closing_mps * closing_mps)
    return std::min(1e3, match_bound_mps2());
  return std::min(1e3, stop_mps2);
}

double chained_accel_mps2(const std::vector<MainLaneVehicle>& lane, const MainLaneVehicle& v,
                          const std::function<double(int)>& observed_accel_mps2, const LeaderHorizon& h) {
  const double seen_mps2 = observed_accel_mps2(v.id);
  const MainLaneVehicle* ahead = next_in_lane(lane, v);
  if (ahead == nullptr) return seen_mps2;
  const double behind_mps2 = braking_behind_mps2(v, *ahead, chained_accel_mps2(lane, *ahead, observed_accel_mps2, h), h);
  return std::min(seen_mps2, -behind_mps2);
}

Track leader_track(const MainLaneVehicle& l, double observed_accel_mps2, const MainLaneVehicle* ahead,
                   double ahead_accel_mps2, const LeaderHorizon& h) {
  const double seen_mps2 = observed_accel_mps2 < -kLeaderBrakingMps2 ? -observed_accel_mps2 : 0.0;
  const double behind_mps2 = ahead ? braking_behind_mps2(l, *ahead, ahead_accel_mps2, h) : 0.0;
  SpeedRamp motion{l.speed_mps, l.speed_mps, 1.0, 1.0};
  // Braking seen to a stop is behind the braking needed to the speed ahead whenever it is harder.
  if (behind_mps2 > seen_mps2) {
    const double to_mps = ahead_accel_mps2 < -kLeaderBrakingMps2 ? 0.0 : ahead->speed_mps;
    motion = SpeedRamp{l.speed_mps, to_mps, 1.0, behind_mps2};
  } else if (seen_mps2 > 0.0) {
    motion = SpeedRamp{l.speed_mps, 0.0, 1.0, seen_mps2};
  }
  return Track{l.x_m, motion, l.length_m, l.width_m, l.limits, 0.0, {}};
}

BesideTrack beside_track(const MainLaneVehicle& v, double lane_y_m, double observed_accel_mps2, double speed_cap_mps) {
  MG_DEMAND(lane_y_m > 0.0);
  // Braking at its b_max from now: nothing in the merge depends on a vehicle of another lane, and
  // one that brakes legally while the ego is laterally close to it (a weak lateral brake makes
  // D_lat reach across a lane) forces the ego's RSS braking in mid-merge, into its own gap's safe
  // distance (a campaign finding, docs/planner.md).
  BesideTrack t{leader_track(v, std::min(observed_accel_mps2, -v.limits.brake_max_mps2)),
                leader_track(v, observed_accel_mps2)};
  // Nominally it keeps accelerating as seen, up to the cap: whether it may be ahead of the ego
  // decides whether it constrains the merge, and one predicted at constant speed while it
  // accelerated beside the ego came out ahead a cycle later, so that each merge planned past it
  // was aborted at its first re-check (a campaign finding, docs/planner.md).
  if (observed_accel_mps2 > 0.0 && speed_cap_mps > v.speed_mps)
    t.nominal.motion = SpeedRamp{v.speed_mps, speed_cap_mps, observed_accel_mps2, 1.0};
  t.braking.lane_y_m = t.nominal.lane_y_m = lane_y_m;
  return t;
}

GapTracks gap_tracks(const std::vector<MainLaneVehicle>& lane, const LaneGap& gap, double follower_window_s,
                     const std::function<double(int)>& observed_accel_mps2, const LeaderHorizon& leader_horizon) {
  GapTracks tracks;
  tracks.followers.reserve(lane.size());
  tracks.leaders.reserve(lane.size());
  for (const MainLaneVehicle& v : lane) {
    if (gap.follower && v.id == gap.follower->id)
      tracks.followers.push_back(follower_track(v, follower_window_s, observed_accel_mps2(v.id)));
    else if (gap.follower && !lane_order_before(*gap.follower, v))
      tracks.followers.push_back(behind_follower_track(v, *gap.follower, follower_window_s, observed_accel_mps2(v.id),
                                                       observed_accel_mps2(gap.follower->id)));
    if (gap.leader && !lane_order_before(v, *gap.leader)) {
      const MainLaneVehicle* ahead = next_in_lane(lane, v);
      tracks.leaders.push_back(
          leader_track(v, observed_accel_mps2(v.id), ahead,
                       ahead ? chained_accel_mps2(lane, *ahead, observed_accel_mps2, leader_horizon) : 0.0, leader_horizon));
    }
  }
  return tracks;
}

namespace {

// The ego at x_m with speed v_mps, t_s after the decision, must be D_lon (RCPP eq. 1) ahead of
// every follower (until P_c) and behind every leader, and every vehicle ahead in another lane,
// it is laterally close to. Closeness is measured by the lateral room, the ego's lateral distance
// beyond D_lat to the target lane's centre for a vehicle as wide as the ego; a wider one needs
// half the width difference more (eq. 2 grows with the width sum), one in another lane lane_y_m
// less. Returns the largest such extra over the vehicles the ego is not D_lon clear of (-inf
// when it is clear of all), for the target lane's and the other lanes' vehicles apart: the
// instant is blocked when the lateral room is below it.
Blocking blocked_below_m(const PlannerSetup& s, double t_s, double x_m, double v_mps, double pc_m, const GapTracks& tracks,
                         double buffer_m) {
  const double t_lag = s.params.rss.response_time_s;
  const Limits& el = s.ego.limits;
  const double le = s.ego.size.length_m;
  Blocking below;
  const auto block = [&](const Track& o, double& extra_m) {
    extra_m = std::max(extra_m, 0.5 * (o.width_m - s.ego.size.width_m) - o.lane_y_m);
  };
  // Not D_lon behind o: the ego as the rear vehicle (RCPP eq. 1).
  const auto too_close_behind = [&](const Track& o) {
    const double d = rss_longitudinal_m({v_mps, o.v_at(t_s), le, o.length_m, t_lag, el.accel_max_mps2,
                                         el.brake_min_mps2, o.limits.brake_max_mps2});
    return x_m + d + buffer_m > o.x_at(t_s);
  };
  if (x_m <= pc_m) {
    for (const Track& f : tracks.followers) {
      const double d = rss_longitudinal_m({f.v_at(t_s), v_mps, f.length_m, le, t_lag, f.limits.accel_max_mps2,
                                           f.limits.brake_min_mps2, el.brake_max_mps2});
      if (x_m - d - buffer_m < f.x_at(t_s)) block(f, below.lane_m);
    }
  }
  for (const Track& l : tracks.leaders)
    if (too_close_behind(l)) block(l, below.lane_m);
  // Another lane's vehicle constrains the merge only while it may be ahead of the ego: judged by
  // its braking position alone, a vehicle the ego would pass once stopped but not if it kept
  // braking a little later (the check a cycle on) drew a merge, an abort and a retry every
  // two seconds (smoothness_oscillation; docs/planner.md).
  for (const BesideTrack& o : tracks.beside)
    if (o.nominal.x_at(t_s) > x_m && too_close_behind(o.braking)) block(o.braking, below.beside_m);
  return below;
}

// The largest extra lateral distance any of the tracks needs (see blocked_below_m).
double widest_extra_m(const PlannerSetup& s, const GapTracks& tracks) {
  double extra = -std::numeric_limits<double>::infinity();
  const auto widen = [&](const Track& o) { extra = std::max(extra, 0.5 * (o.width_m - s.ego.size.width_m) - o.lane_y_m); };
  for (const auto* list : {&tracks.followers, &tracks.leaders})
    for (const Track& o : *list) widen(o);
  for (const BesideTrack& o : tracks.beside) widen(o.braking);
  return extra;
}

double ego_lateral_rss_m(const PlannerSetup& s, double lat_speed_mps) {
  const Limits& el = s.ego.limits;
  return rss_lateral_m({0.0, lat_speed_mps, s.ego.size.width_m, s.ego.size.width_m, s.params.rss.response_time_s,
                        el.lat_accel_max_mps2, el.lat_brake_min_mps2, s.params.rss.fluctuation_margin_m});
}

// The ego on its path at one instant: its lateral room beyond D_lat (and the tracking margin) to
// the target lane's centre, for the body's corner on its heading (room_m) and for its centre
// (centre_room_m), and whether a corner is over the lane line.
struct PathLateral {
  double room_m = 0.0;
  double centre_room_m = 0.0;
  bool over_line = false;
};

PathLateral path_lateral(const PlannerSetup& s, double ego_y_m, const Sigmoid& sig, double x, double v) {
  const double y_path = sig.y_at_m(x);
  const double sgm = (y_path - sig.offset_m) / sig.width_m;
  // An ego nearer the lane than the path's start is not assumed to have reached the path yet.
  const double y = std::max(y_path, ego_y_m);
  const double slope = sig.width_m * sig.kappa_per_m * sgm * (1.0 - sgm);  // dY/dX on the path
  const double d_lat = ego_lateral_rss_m(s, v * slope);
  // The ego's half extent across the road on its heading along the path: the box's corner, not
  // its side, comes nearest the lane (a halted ego, yawed 0.07 rad, had its corner 7 cm over
  // the lane line while the vehicle it was to merge behind passed; a campaign finding).
  const double cos_h = 1.0 / std::sqrt(1.0 + slope * slope);
  const double yaw_extra_m = 0.5 * (s.ego.size.width_m * (cos_h - 1.0) + s.ego.size.length_m * slope * cos_h);
  // Laterally safe (lane centre Y = 0), with the tracking margin growing with the path's progress
  // from the side lane's centre (for the paper's path, its own fraction sgm): a path drawn from an
  // ego off that centre (merge_sigmoid) starts where the ego may still be moving, and one held
  // 1.5 cm outside D_lat of a truck closing from behind took the ego, as it settled, inside it.
  const double from_centre = (y_path - s.road.side_lane_y_m()) / s.road.lane_width_m;
  const double margin_m = kOccupancyLateralMarginM * std::clamp(from_centre / kOccupancyFullMarginFraction, 0.0, 1.0);
  // A corner over the lane line (with kLaneLineMarginM) is in the lane, whatever D_lat says:
  // the rules judge entry by it (docs/spec.md §8).
  return {-y - yaw_extra_m - (d_lat + margin_m), -y - (d_lat + margin_m),
          -y - yaw_extra_m - 0.5 * s.ego.size.width_m < 0.5 * s.road.lane_width_m + kLaneLineMarginM};
}

constexpr double kNone = -std::numeric_limits<double>::infinity();

// One occupancy check's instants (occupancy_clear).
struct OccupancyScan {
  const PlannerSetup& s;
  double ego_x_m, ego_y_m;
  const Sigmoid& sig;
  double pc_m;  // where the path crosses the lane line (lane_line_x_m): the same for every kappa of a ramp
  const SpeedRamp& ego;
  const OccupancyInstants& when;
  const GapTracks& tracks;
  double buffer_m;
  double lateral_slack_m;
  OccupancyMemo* memo;
  double widest_extra = std::numeric_limits<double>::quiet_NaN();  // computed when first needed

  bool blocked_at(int k) {
    const double t = std::max(0.0, k * when.step_s - when.elapsed_s);
    const bool memoised = memo && k <= kOccupancySamples;
    Blocking below = memoised ? memo->blocked_below_m[static_cast<std::size_t>(k)] : Blocking{std::nan(""), 0.0};
    // An instant at which the ego is D_lon clear of every vehicle is clear for every candidate of
    // this ramp, whatever its lateral position: then neither the ramp nor the path is evaluated.
    if (below.lane_m == kNone && below.beside_m == kNone) return false;
    const double x = ego_x_m + ego.distance_at_m(t);
    const double v = ego.speed_at_mps(t);
    if (memoised && std::isnan(below.lane_m)) {  // filled first: it does not depend on kappa
      below = blocked_below_m(s, t, x, v, pc_m, tracks, buffer_m);
      memo->blocked_below_m[static_cast<std::size_t>(k)] = below;
      if (below.lane_m == kNone && below.beside_m == kNone) return false;
    }
    const PathLateral lat = path_lateral(s, ego_y_m, sig, x, v);
    // Without the instant's Blocking, a first test against the widest extra of any track (it bounds
    // both parts, so a room above it is clear unless over the line); with it, it decides alone.
    if (std::isnan(below.lane_m)) {
      if (std::isnan(widest_extra)) widest_extra = widest_extra_m(s, tracks);
      if (!lat.over_line && std::min(lat.room_m, lat.centre_room_m) + lateral_slack_m >= widest_extra) return false;
      below = blocked_below_m(s, t, x, v, pc_m, tracks, buffer_m);
    }
    const bool lane_blocked = below.lane_m > kNone && (lat.over_line || lat.room_m + lateral_slack_m < below.lane_m);
    // A vehicle of another lane is judged by RCPP eq. (2) between centres (rss_lateral), whatever
    // the ego's yaw: the corner, which decides where the ego enters its target lane, would keep a
    // merge from passing a vehicle of the lane beyond at the D_lat and tracking margin the rules
    // and the progress rule's witness keep.
    return lane_blocked || lat.centre_room_m + lateral_slack_m < below.beside_m;
  }
};

}  // namespace

bool occupancy_clear(const PlannerSetup& s, double ego_x_m, double ego_y_m, const Sigmoid& sig, const SpeedRamp& ego,
                     const OccupancyInstants& when, const GapTracks& tracks, double buffer_m, OccupancyMemo* memo,
                     double lateral_slack_m) {
  MG_DEMAND(when.step_s > 0.0);
  // The instants k step - elapsed within [0, horizon]: k from k_first to k_last.
  const int k_first = static_cast<int>(std::ceil(when.elapsed_s / when.step_s - 1e-9));
  const int k_last = static_cast<int>(std::floor((when.horizon_s + when.elapsed_s) / when.step_s + 1e-9));
  // Every instant must be clear, so the order is free: from the middle of the decision's horizon
  // (about P_c) back to the first instant, then on to the last. Rejections concentrate just before
  // P_c (the follower), so most come after a few instants.
  const int k_middle = std::clamp(kOccupancySamples / 2, k_first, std::max(k_first, k_last));
  OccupancyScan scan{s, ego_x_m, ego_y_m, sig, lane_line_x_m(sig, s.road.lane_width_m), ego, when, tracks,
                     buffer_m, lateral_slack_m, memo};
  const int hint = memo && memo->last_blocked_k >= k_first && memo->last_blocked_k <= k_last ? memo->last_blocked_k : -1;
  if (hint >= 0 && scan.blocked_at(hint)) return false;
  for (int j = 0; j <= k_last - k_first; ++j) {
    const int k = j <= k_middle - k_first ? k_middle - j : k_first + j;
    if (k == hint) continue;  // clear, just checked
    if (scan.blocked_at(k)) {
      if (memo) memo->last_blocked_k = k;
      return false;
    }
  }
  return true;
}

}  // namespace mg
