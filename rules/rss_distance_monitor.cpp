#include "rules/rss_distance_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "rules/near_pairs.h"


namespace mg {
namespace {

constexpr double kNever = -std::numeric_limits<double>::infinity();

struct Episode {
  bool active = false;
  double blame_time_s = 0.0;
  bool lateral_entrance = false;  // lateral distance became unsafe last (a cut-in)
  Party breach = Party::nobody();
  double response_speed_mps = 0.0;  // lateral: ego speed toward the other at t_b + T
  bool response_speed_set = false;
  std::size_t rear = 0;       // longitudinal: the pair's rear vehicle (trace index) ...
  double rear_since_s = 0.0;  // ... and since when: side by side, the order can flip mid-episode
  // Lateral: when the ego's duty began, t_b or the end of its waived merge motion (NaN: waived).
  double duty_since_s = std::numeric_limits<double>::quiet_NaN();
};

std::size_t pair_count(std::size_t n) { return n * (n - 1) / 2; }

std::string describe(const ObservedTrace& s, std::size_t k) { return party_name(party_of(s, k)); }

// Interaction bound of RCPP eq. (1): whatever the front vehicle does, D_lon <= (l_r + l_f)/2 + the
// rear vehicle's worst-case stopping distance v T + a T^2/2 + (v + a T)^2 / (2 b_min) (the front
// vehicle only moves forward). reach_m = that distance + l_r/2, padded against rounding.
double lon_reach_m(const ObservedTrace& s, std::size_t v, double road_vx_mps) {
  const Limits& l = limits_of(s, v);
  const double T = s.params.rss.response_time_s, speed = std::max(road_vx_mps, 0.0);
  const double after_t = speed + l.accel_max_mps2 * T;
  const double stop_m = speed * T + 0.5 * l.accel_max_mps2 * T * T + after_t * after_t / (2.0 * l.brake_min_mps2);
  return (0.5 * size_of(s, v).length_m + stop_m) * (1.0 + 1e-9) + 1e-9;
}

// gap - (that bound) for vehicles i, j: when >= 0 the pair is longitudinally safe (gap >= D_lon).
double slack_beyond_reach_m(const ObservedTrace& s, const PairStepper& pairs, const std::vector<double>& reach_m,
                            std::size_t i, std::size_t j) {
  const bool i_rear = pairs.x_m(i) <= pairs.x_m(j);
  const std::size_t rear = i_rear ? i : j, front = i_rear ? j : i;
  const double gap_m = pairs.x_m(front) - pairs.x_m(rear);
  return gap_m - (reach_m[rear] + 0.5 * size_of(s, front).length_m * (1.0 + 1e-9));
}

// A pair that far apart is longitudinally safe, so its only effect would be a margin
// gap - D_lon >= the slack: when that is not below the smallest margin so far, it changes
// nothing (exact) and the pair's RSS distances are not computed.
bool far_apart(const ObservedTrace& s, const PairStepper& pairs, const std::vector<double>& reach_m, std::size_t i,
               std::size_t j, double min_margin) {
  const double slack_m = slack_beyond_reach_m(s, pairs, reach_m, i, j);
  return slack_m >= 0.0 && slack_m >= min_margin;
}

}  // namespace

MonitorOutput monitor_rss_longitudinal(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  const std::size_t n = s.vehicles.size();
  const double T = s.params.rss.response_time_s;
  const double tol = ctx.params.accel_tolerance_mps2;
  MarginAccumulator acc("rss_longitudinal", steps.size());
  std::vector<Episode> episodes(pair_count(n));
  std::vector<double> last_overbrake(n, kNever);
  std::vector<char> prev_lon_only(pair_count(n), 0);  // previous step: lon unsafe, lat safe
  // Below this speed a vehicle braking at b_min stops within one step (its applied
  // acceleration over that step is then smaller): it counts as stopped.
  std::vector<double> stop_speed(n);
  for (std::size_t v = 0; v < n; ++v)
    stop_speed[v] = ctx.params.halted_speed_mps + limits_of(s, v).brake_min_mps2 * step_interval_s(s);
  PairStepper pairs(s);
  NearPairs near;
  std::vector<double> reach_m(n), lo_m(n), hi_m(n);
  std::vector<std::size_t> seen_step(pair_count(n), steps.size());  // main-lane pairs: last step visited
  double max_half_length_m = 0.0;
  for (std::size_t v = 0; v < n; ++v) max_half_length_m = std::max(max_half_length_m, 0.5 * size_of(s, v).length_m);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const ObservedStep& st = steps[k];
    pairs.load(st);
    for (std::size_t v = 0; v < n; ++v) {
      reach_m[v] = lon_reach_m(s, v, pairs.road_vx_mps(v));
      lo_m[v] = pairs.x_m(v);
      hi_m[v] = lo_m[v] + reach_m[v] + max_half_length_m * (1.0 + 1e-9) + 1e-6;  // >= any bound with v as rear
    }
    for (std::size_t v = 0; v < n; ++v) {
      if (state_of(st, v).accel_mps2 < -(limits_of(s, v).brake_max_mps2 + tol)) last_overbrake[v] = st.time_s;
    }
    const auto visit = [&](std::size_t p, std::size_t i, std::size_t j) {
      const PairGeometry g = pairs.at(p, i, j);
      Episode& e = episodes[p];
      const bool was_lon_only = prev_lon_only[p] != 0;
      prev_lon_only[p] = g.lon_unsafe() && !g.lat_unsafe();
      if (!g.lat_unsafe() || !g.lon_unsafe()) {
        e.active = false;
        if (g.lat_unsafe()) acc.record(k, st.time_s, g.gap_m - g.d_lon_m, Party::nobody(), g.d_lon_m, g.gap_m);
        return;
      }
      if (!e.active) {
        // A cut-in: the lateral distance became unsafe last, with the ego moving toward the other
        // vehicle. An ego that only stops moving away (D_lat grows as its speed away falls to 0)
        // did not enter: it is where it was, e.g. off-centre in the side lane (docs/rules.md).
        const bool ego_in_pair = i == 0 || j == 0;
        const double ego_toward_mps = g.right == 0 ? ego_of(st).vy_mps : -ego_of(st).vy_mps;
        e = Episode{true, st.time_s, was_lon_only && ego_in_pair && ego_toward_mps > 0.0, Party::nobody(), 0.0, false,
                    g.rear, st.time_s};
      }
      if (g.rear != e.rear) {
        e.rear = g.rear;
        e.rear_since_s = st.time_s;
      }
      const ObservedState& rear = state_of(st, g.rear);
      std::string why;
      if (e.breach == Party::nobody()) {
        if (last_overbrake[g.front] >= e.blame_time_s - T - kTieS) {
          e.breach = party_of(s, g.front);
          why = describe(s, g.front) + " braked harder than its declared b_max " +
                std::to_string(limits_of(s, g.front).brake_max_mps2) + " m/s2 while " +
                describe(s, g.rear) + " followed";
        } else if (rear.accel_mps2 > limits_of(s, g.rear).accel_max_mps2 + tol) {
          // RSS Def. 1's worst case bounds the rear vehicle's acceleration by its a_accel^max even
          // during the response time; beyond it, D_lon no longer covers the pair.
          e.breach = party_of(s, g.rear);
          std::ostringstream os;
          os << describe(s, g.rear) << " accelerated at " << rear.accel_mps2 << " m/s2, beyond its declared a_accel^max "
             << limits_of(s, g.rear).accel_max_mps2 << " m/s2, while the situation was dangerous (since t = "
             << e.blame_time_s << " s)";
          why = os.str();
        } else if (e.lateral_entrance && !ctx.row.ego_held_toward_within(i == 0 ? j : i, e.blame_time_s - T - kTieS,
                                                                          e.blame_time_s + kTieS)) {
          // The right of way toward this vehicle: a merge covered toward the gap's other vehicle
          // only is a cut-in toward this one (rules/liability.h).
          // An ego that held the right of way within the last T (it aborted its merge) is still
          // within its response time: its lateral motion is then rss_lateral's to judge. An ego
          // still within merge_start_offset_m of its own lane's centre is not cutting in yet,
          // and the danger its lateral motion made is not the rear vehicle's either:
          // rss_lateral judges that motion, and the blame waits for the ego to move on.
          if (ego_of(st).y_m > s.road.side_lane_y_m() + ctx.params.merge_start_offset_m) {
            e.breach = Party::ego();
            why = "ego entered the lane of " + describe(s, i == 0 ? j : i) +
                  " at an unsafe longitudinal distance without the right of way";
          }
        } else if (st.time_s >= std::max(e.blame_time_s, e.rear_since_s) + T - 1e-9 &&
                   speed_of(rear) > stop_speed[g.rear] &&
                   rear.accel_mps2 > -(limits_of(s, g.rear).brake_min_mps2 - tol)) {
          e.breach = party_of(s, g.rear);
          std::ostringstream os;
          os << describe(s, g.rear) << " did not brake at least b_min "
             << limits_of(s, g.rear).brake_min_mps2 << " m/s2 (applied " << rear.accel_mps2
             << " m/s2) " << T << " s after the situation became dangerous at t = " << e.blame_time_s << " s";
          if (e.rear_since_s > e.blame_time_s) os << " (the rear vehicle since t = " << e.rear_since_s << " s)";
          why = os.str();
        }
      }
      const double margin = e.breach == Party::nobody() ? 0.0 : g.gap_m - g.d_lon_m;
      if (acc.record(k, st.time_s, margin, e.breach, g.d_lon_m, g.gap_m)) acc.set_detail(why);
    };
    // Pair order as over all pairs: the ego's pairs (p = j - 1) first, then the main-lane pairs
    // near enough to matter. A main-lane pair left out, laterally safe, or too far apart to lower
    // the minimum does nothing but end its episode (prev_lon_only is read for ego pairs only).
    for (std::size_t j = 1; j < n; ++j) {
      if (far_apart(s, pairs, reach_m, 0, j, acc.min_margin())) {
        prev_lon_only[j - 1] = 0;  // longitudinally safe
        episodes[j - 1].active = false;
      } else {
        visit(j - 1, 0, j);
      }
    }
    for (const auto& [i, j] : near.find(lo_m, hi_m, acc.min_margin())) {
      if (i == 0) continue;
      const std::size_t p = PairStepper::index(n, i, j);
      if (seen_step[p] + 1 != k) episodes[p].active = false;  // left out at the previous step
      seen_step[p] = k;
      if (far_apart(s, pairs, reach_m, i, j, acc.min_margin()) || !pairs.lat_unsafe(p, i, j)) {
        episodes[p].active = false;
        continue;
      }
      visit(p, i, j);
    }
  }
  return acc.finish();
}

MonitorOutput monitor_rss_lateral(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  const std::size_t n = s.vehicles.size();
  const double T = s.params.rss.response_time_s;
  const double tol = ctx.params.speed_tolerance_mps;
  MarginAccumulator acc("rss_lateral", steps.size());
  std::vector<Episode> episodes(n - 1);  // only ego pairs: main-lane vehicles keep their lane
  PairStepper pairs(s);
  std::vector<double> reach_m(n);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const ObservedStep& st = steps[k];
    pairs.load(st);
    for (std::size_t v = 0; v < n; ++v) reach_m[v] = lon_reach_m(s, v, pairs.road_vx_mps(v));
    for (std::size_t j = 1; j < n; ++j) {
      if (slack_beyond_reach_m(s, pairs, reach_m, 0, j) >= 0.0) {  // longitudinally safe: not dangerous
        episodes[j - 1].active = false;
        continue;
      }
      const PairGeometry g = pairs.at(PairStepper::index(n, 0, j), 0, j);
      Episode& e = episodes[j - 1];
      // With the ego's centre in the other vehicle's lane the pair is a same-lane pair: its
      // distance is rss_longitudinal's (a cut-in is judged there), and the ego centring itself in
      // its lane is not a lateral approach.
      if (std::abs(g.dy_m) < 0.5 * s.road.lane_width_m) {
        e.active = false;
        continue;
      }
      if (!g.lon_unsafe() || !g.lat_unsafe()) {
        e.active = false;
        if (g.lon_unsafe()) acc.record(k, st.time_s, g.dy_m - g.d_lat_m, Party::nobody(), g.d_lat_m, g.dy_m);
        continue;
      }
      if (!e.active) e = Episode{true, st.time_s, false, Party::nobody(), 0.0, false};
      // The right of way is the right to merge into the rightmost main lane (centre Y = 0): it
      // waives the ego's lateral duty for the motion of that merge, leftward up to the lane's
      // centre, toward whichever vehicle; not a motion beyond it, nor toward a vehicle on the
      // ego's right (spec §8, "The ego's lateral duty": the waiver follows the manoeuvre, not the clock).
      const bool merge_motion = g.right == 0 && ego_of(st).y_m < 0.0;
      const bool obliged = !(merge_motion && ctx.row.ego_holds_toward_at(j, e.blame_time_s));
      // A duty that starts mid-episode (the merge motion ends at the lane's centre) gets its
      // response time from then, as one that starts with the danger does: the ego cannot have
      // answered, during a waiver, a duty it did not have yet.
      if (obliged && std::isnan(e.duty_since_s)) e.duty_since_s = st.time_s;
      const double toward = g.right == 0 ? ego_of(st).vy_mps : -ego_of(st).vy_mps;
      std::string why;
      if (obliged && e.breach == Party::nobody() && st.time_s >= e.duty_since_s + T - 1e-9) {
        if (!e.response_speed_set) {
          e.response_speed_mps = toward;
          e.response_speed_set = true;
        }
        const double allowed =
            std::max(0.0, e.response_speed_mps - limits_of(s, 0).lat_brake_min_mps2 * (st.time_s - e.duty_since_s - T));
        if (toward > allowed + tol) {
          e.breach = Party::ego();
          std::ostringstream os;
          os << "ego kept moving toward " << describe(s, j) << " at " << toward
             << " m/s laterally (allowed " << allowed << " m/s) without the right of way, "
             << T << " s after the lateral danger began at t = " << e.blame_time_s << " s";
          if (e.duty_since_s > e.blame_time_s) os << " (its duty since t = " << e.duty_since_s << " s, the end of its merge motion)";
          why = os.str();
        }
      }
      const double margin = e.breach == Party::nobody() ? 0.0 : g.dy_m - g.d_lat_m;
      if (acc.record(k, st.time_s, margin, e.breach, g.d_lat_m, g.dy_m)) acc.set_detail(why);
    }
  }
  return acc.finish();
}

}  // namespace mg
