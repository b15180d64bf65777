// The merge path's admissibility and the lane-occupancy check along it (RCPP §II-C, spec §6):
// pure functions of the RCPP planner (docs/planner.md). The progress rule judges what merge it
// offers with its own code (rules/feasible_gaps.h): rules/ never includes the planner.
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "core/scenario.h"
#include "planner/definition1.h"
#include "planner/sigmoid.h"

namespace mg {

// ln(f / (1 - f)): kappa times the distance from P_c to where the sigmoid has covered f of W.
double ln_ratio(double fraction);
// Distance from the start of the sigmoid (within kSigmoidEndFraction of the side lane) to P_c,
// times kappa; the same from P_c to completion.
double half_span_times_kappa();
// Fraction of the lateral offset after which the ego's right edge has left the side lane,
// 1/2 + w/(2W), clamped into the sigmoid.
double side_lane_exit_fraction(double ego_width_m, double lane_width_m);
// The x the ego's centre may reach at most while its sigmoid still has `exit` left to cover:
// the side lane's end minus half the ego length (spec §2: never pass the end in the side lane)
// minus a margin for path-tracking lag: kSideExitMarginM, or kSideExitLagS of travel at
// speed_mps when longer (an ego at 33 m/s crossed the lane line 10 m after its P_c and left
// the road 2 mm past the side lane's end; a campaign finding).
inline constexpr double kSideExitMarginM = 5.0;
inline constexpr double kSideExitLagS = 0.4;
double side_exit_limit_x_m(const PlannerSetup& s, double speed_mps = 0.0);

// Trackability of a path at any speed: its curvature c stays within half the ego's steering
// ability (tan(steer_max)/(2 wheelbase)) and keeps the kinematic sideslip atan(l_r c) below
// kPathSideslipMaxRad, half the sideslip rule's bound (docs/planner.md). For the sigmoid, whose
// peak curvature is W kappa^2/(6 sqrt 3), that caps kappa.
inline constexpr double kPathSideslipMaxRad = 0.025;
double path_curvature_cap_per_m(const PlannerSetup& s);
// The sharpest curvature a merge may have: the envelope the simulator's path tracker steers in (a
// kinematic sideslip of kPathTrackerSideslipRad with the ego's l_r; sim/path_tracker.h), within
// half the steering ability (kappa_sharpest_per_m).
inline constexpr double kPathTrackerSideslipRad = 0.035;
double merge_curvature_cap_per_m(const PlannerSetup& s);
// A crawl: a merge driven no faster than kCrawlSpeedFraction of the speed from which the judge
// bounds the sideslip (rules.sideslip_min_speed_mps, public like the speed limit; docs/rules.md
// `sideslip`). Below it the sideslip bound constrains no path, so a crawl's curvature is capped by
// half the ego's steering ability alone: an ego halted short of the side lane's end, with too
// little room for a sideslip-bounded sigmoid, can still merge at walking pace (docs/planner.md).
inline constexpr double kCrawlSpeedFraction = 0.7;
double crawl_speed_mps(const PlannerSetup& s);
// The curvature cap of a path driven at most at top_speed_mps: path_curvature_cap_per_m, or at
// crawl speed the steering-only cap.
double path_curvature_cap_per_m(const PlannerSetup& s, double top_speed_mps);
// The linear single-track model's steady-state sideslip per unit path curvature at speed v,
// beta / c = l_r - m l_f v^2 / (C_r L) (rear axle: F_yr = m v^2 c l_f / L = C_r alpha_r and
// beta = l_r c - alpha_r; Rajamani, Vehicle Dynamics and Control, 2nd ed., §3.3). At a crawl it is
// the kinematic l_r; at speed, with soft rear tyres, many times larger and of the other sign.
double steady_sideslip_per_curvature_m(const EgoDynamics& d, double speed_mps);
double kappa_cap_per_m(const PlannerSetup& s);
double kappa_cap_per_m(const PlannerSetup& s, double top_speed_mps);
double kappa_cap_per_m(const PlannerSetup& s, const SpeedRamp& ramp);  // at the ramp's top speed
// The sharpest kappa of a merge driven at most at top_speed_mps, used only where no sigmoid within
// kappa_cap_per_m fits (kappa_range_for): the tracker's envelope (merge_curvature_cap_per_m), or
// the crawl's cap if larger. The `progress` rule's witness merge turns in within a share of the
// sideslip bound (rules/feasible_gaps.h); within half of it RCPP let pass merges from low speed whose
// turn-in or second half was a metre or two too short. Where the half bound fits it is kept, and
// a sharper candidate pays sharp_sigmoid_penalty: tracked further behind, sharper sigmoids taken
// for their lower cost put merges the re-check then aborted. The room the halt point leaves for a
// merge from standstill keeps the half bound too.
double kappa_sharpest_per_m(const PlannerSetup& s, double top_speed_mps);
// What a candidate sigmoid sharper than kappa_cap_per_m of its ramp adds to its cost
// (kSharpSigmoidPenalty, far above any candidate's cost, and above the Definition 1 search's
// penalty for a P_c near its bound; else 0), so that a search takes it only when nothing within
// the cap is admissible, not even near a P_c bound. The cap is computed once per ramp.
inline constexpr double kSharpSigmoidPenalty = 1e5;
inline double sharp_sigmoid_penalty(double kappa_per_m, double kappa_cap_per_m) {
  return kappa_per_m > kappa_cap_per_m ? kSharpSigmoidPenalty : 0.0;
}

// Admissible kappa for a sigmoid with midpoint pc_m: starts at the ego (within the end fraction at
// start_x_m), completes by complete_by_x_m, leaves the side lane before its end, keeps the peak
// lateral acceleration along the ego's speed profile (ramp from ramp_origin_x_m) within the comfort
// bound, and lies in the configured [kappa_min, kappa_max] and under the curvature cap of the
// ramp's top speed (kappa_cap_per_m; where the other bounds lie above it, kappa_sharpest_per_m).
// kappa_floor_per_m replaces the configured kappa_min_per_m when positive (the flat fallback of
// the Definition 1 search, kFlatKappaFloorPerM).
// An ego that starts at a crawl or at rest (the ramp's start speed at most crawl_speed_mps) and
// accelerates beyond the crawl may start where the sigmoid is at start_fraction of the lane change,
// its own lateral progress toward the main lane, instead of at the end fraction: a merge that
// keeps the ego's offset (CommittedMerge::from_hold) meets the sigmoid there, at the ego, where the
// heading's kink is taken at a crawl; one that does not lies no lower there than from the end
// fraction. Only where no sigmoid from the end fraction fits under the curvature cap and one from
// start_fraction does (the cap itself still applies). An ego halted off its centre near the side
// lane's end otherwise found no sigmoid from its 2 % point that also left the side lane before
// its end (`progress`, whose witness starts from the ego's offset; a campaign finding). Not for a
// ramp that stays at a crawl, nor beyond the cap: such a path, steeper, was tracked so far
// behind it that a corner left the road at the side lane's end.
KappaRange kappa_range_for(const PlannerSetup& s, double pc_m, double start_x_m, double complete_by_x_m,
                           const SpeedRamp& ramp, double ramp_origin_x_m, double kappa_floor_per_m = 0.0,
                           double start_fraction = kSigmoidEndFraction);

// A vehicle a track cannot pass, being behind it in the same lane: its own motion from x0_m, and
// the bumper-to-centre distance the track keeps behind it (half both lengths and kLeaderStandoffM).
struct BehindBound {
  bool active = false;
  double x0_m = 0.0;
  SpeedRamp motion;
  double standoff_m = 0.0;
  double x_at(double t_s) const { return x0_m + motion.distance_at_m(t_s) - standoff_m; }
};

// A main-lane vehicle's predicted motion during a merge candidate: from x0_m, one speed ramp, on
// the lane centred at lane_y_m (0: the merge's target lane); with `behind` active, never past the
// vehicle ahead of it, and no faster than it once it has caught up.
struct Track {
  double x0_m = 0.0;
  SpeedRamp motion;
  double length_m = 0.0;
  double width_m = 0.0;
  Limits limits;
  double lane_y_m = 0.0;
  BehindBound behind;
  double x_at(double t_s) const;  // t after the decision
  double v_at(double t_s) const;
};

// The follower accelerates at its a_accel^max until rho/2 and then holds its speed (Def. 1.1);
// one seen accelerating harder than that, at the rate seen (a follower racing beyond its declared
// limit took the gap an ego planned to overtake it into; a campaign finding).
Track follower_track(const MainLaneVehicle& f, double rho_s, double observed_accel_mps2 = 0.0);
// A vehicle behind the gap's follower, predicted like a follower but bounded by the follower's own
// track: it cannot drive through the follower (a vehicle approaching a stopped follower, predicted
// to accelerate past it, barred every merge ahead of the stopped one; a campaign finding).
Track behind_follower_track(const MainLaneVehicle& v, const MainLaneVehicle& follower, double rho_s,
                            double observed_accel_mps2, double follower_accel_mps2);
// The leader holds its speed (Def. 1.2) unless it is seen braking harder than
// kLeaderBrakingMps2: then it is predicted to keep braking at that rate until it stops, since a
// compliant leader may brake for a slower vehicle ahead of it (docs/planner.md); a rate beyond its
// declared b_max is taken as seen, not capped.
// With `ahead`, the vehicle in front of the leader in its lane: a leader cannot drive through it,
// so it is predicted to slow to that vehicle's speed (`ahead` at constant speed), uniformly, by
// kLeaderStandoffM behind it, or to stop kLeaderStandoffM behind where `ahead` stops when that
// one is seen braking (at ahead_accel_mps2), whenever that needs more than the braking seen
// (however little: no noise threshold applies). A leader that brakes later and harder for the
// same vehicle is ahead of this prediction all the way, so a merge planned behind it is not
// aborted when its braking sets in (docs/planner.md "Predicting the other vehicles").
inline constexpr double kLeaderBrakingMps2 = 0.5;
inline constexpr double kLeaderStandoffM = 2.0;
// How long the prediction of a leader is needed (the rest of the merge it bounds). A leader that,
// at its speed, is still RCPP eq. (1)'s D_lon behind `ahead` (braking as predicted) at
// horizon_s needs no braking for it within the horizon and is predicted at its speed: the
// progress rule offers such a gap (rules/feasible_gaps.cpp, leader_holds_speed), and a leader
// predicted to brake from now to a stop behind a faster vehicle 80 m ahead seen braking for an
// instant crossed the P_c bounds of every merge into the gap behind it (a campaign finding). With
// no horizon (infinite) the braking is predicted whatever the distance.
struct LeaderHorizon {
  double horizon_s = std::numeric_limits<double>::infinity();
  double response_time_s = 0.0;  // RSS's rho of eq. (1)
};
Track leader_track(const MainLaneVehicle& l, double observed_accel_mps2, const MainLaneVehicle* ahead = nullptr,
                   double ahead_accel_mps2 = 0.0, const LeaderHorizon& h = {});
// The uniform braking leader_track predicts for `l` behind `ahead`: the least that keeps
// kLeaderStandoffM behind `ahead` (at constant speed, or braking to a stop at the rate seen), so
// no harder than stopping behind where a braking `ahead` stops unless the speeds match while it
// still moves; 0 when `l` is not faster than a non-braking `ahead`, even inside the standoff.
// Capped at 1e3 m/s2 (no room left).
// 0 too when `l` holds its speed behind `ahead` until h.horizon_s (LeaderHorizon).
double braking_behind_mps2(const MainLaneVehicle& l, const MainLaneVehicle& ahead, double ahead_accel_mps2 = 0.0,
                           const LeaderHorizon& h = {});
// The vehicle next ahead of `v` in `lane` (any order), or nullptr.
const MainLaneVehicle* next_in_lane(const std::vector<MainLaneVehicle>& lane, const MainLaneVehicle& v);
// The acceleration to predict `v` with as the vehicle ahead of a leader (leader_track's
// ahead_accel_mps2): its observed one, or, when that is harder, minus the braking it needs behind
// the vehicle ahead of it as that one is predicted, and so on to the front of the lane. A vehicle
// seen braking is predicted to stop, so one that must brake for a vehicle stopped further ahead
// is too: a leader predicted behind a fast vehicle alone, which then braked for a stopped one
// ahead of it, aborted the merge planned behind the leader (docs/planner.md).
double chained_accel_mps2(const std::vector<MainLaneVehicle>& lane, const MainLaneVehicle& v,
                          const std::function<double(int)>& observed_accel_mps2, const LeaderHorizon& h = {});

// The vehicles a merge into a gap is checked against: the gap's follower and every target-lane
// vehicle behind it (followers, follower_track over follower_window_s, those behind the follower
// bounded by it: behind_follower_track), its leader and every
// vehicle ahead of it (leaders, leader_track with each one's observed acceleration). Vehicles of
// one lane cannot pass each other, but their separate predictions can: a fast leader predicted
// at constant speed "passes" a slower vehicle ahead of it, and the ego, merging behind the leader,
// would merge onto that vehicle. So the ego must be clear of each of them (docs/planner.md).
// beside: the vehicles of the other main lanes (lane_y_m > 0). The merge brings the ego toward
// them too, and with a long response time or a weak lateral brake its lateral speed alone can
// make D_lat reach across a lane: a vehicle there that the ego is not D_lon behind is then an
// RSS-dangerous situation with the ego as the rear vehicle, whose proper response (braking)
// leaves the planned merge (a campaign finding, docs/planner.md). Predicted like leaders.
// A vehicle of another main lane may brake at any rate up to its b_max: at an instant it can be
// anywhere between its hardest-braking position and its nominal one (leader_track). The ego must
// be D_lon behind the braking position unless it is ahead of the nominal one: in between, some
// legal braking puts the vehicle just ahead of it (docs/planner.md "Predicting the other
// vehicles").
struct BesideTrack {
  Track braking;
  Track nominal;
};
struct GapTracks {
  std::vector<Track> followers;
  std::vector<Track> leaders;
  std::vector<BesideTrack> beside;
};
GapTracks gap_tracks(const std::vector<MainLaneVehicle>& lane, const LaneGap& gap, double follower_window_s,
                     const std::function<double(int)>& observed_accel_mps2, const LeaderHorizon& leader_horizon = {});
// A vehicle of another main lane, centred at lane_y_m > 0, for GapTracks::beside: nominally at
// its observed acceleration while that is positive, up to speed_cap_mps (the road's speed limit),
// else as leader_track predicts it.
BesideTrack beside_track(const MainLaneVehicle& v, double lane_y_m, double observed_accel_mps2, double speed_cap_mps);

// Lane-occupancy check of a candidate (conservative addition to the paper's instants rho/2 and
// rho, docs/planner.md): at every one of kOccupancySamples instants of [0, rho] at which the
// ego on its sigmoid is laterally closer to the main lane centre than D_lat (RCPP eq. 2, with its
// lateral speed on the path and each lane vehicle's width) plus a tracking margin, it must also be
// at least D_lon (RCPP eq. 1) behind that vehicle if it is a leader and, until it reaches P_c,
// ahead of it if it is a follower; and laterally D_lat (plus the margin) from the centre of
// another lane unless D_lon behind each vehicle ahead of it there: the merge never creates an
// RSS-dangerous situation with a main-lane vehicle. The ego starts at ego_y_m, which may be nearer the lane than the sigmoid's start (an
// ego off its lane centre): until the path passes that offset, the ego is taken to stay there (it
// converges to the path, away from the lane). Past P_c the ego is in the lane with the right of
// way, and keeping D_lon behind it is the follower's duty as the rear vehicle (RSS Def. 1; spec
// §8), not something the ego's path must foresee for a follower that keeps the speed Def. 1.1
// allows it to gain. The tracking margin, kOccupancyLateralMarginM, grows with the lateral
// progress: on the side lane's centre, before the sigmoid starts, there is no tracking error.
inline constexpr int kOccupancySamples = 40;
inline constexpr double kOccupancyLateralMarginM = 0.75;
inline constexpr double kOccupancyFullMarginFraction = 0.1;  // full margin from 10 % of W on
// A corner of the ego this near the lane line counts as over it (the rules' marking tolerance,
// 0.05 m, and as much again for tracking).
inline constexpr double kLaneLineMarginM = 0.1;
// buffer_m is added to every D_lon: a new merge is planned with kOccupancyPlanningBufferM, so
// that its re-check every cycle (with none) does not fail at the first small deviation of the
// ego or the traffic from the prediction and abort a merge that has only just begun.
inline constexpr double kOccupancyPlanningBufferM = 1.5;
// lateral_slack_m is lateral room an instant may lack and still be clear: a committed merge's
// re-check takes kOccupancyRecheckLateralSlackM of the tracking margin (kOccupancyLateralMarginM),
// so that a lateral deviation of centimetres from the path does not abort a merge the check
// passed when it was decided (a merge passing a vehicle alongside failed its re-check by 1 cm).
inline constexpr double kOccupancyRecheckLateralSlackM = 0.1;
// The instants a check visits: k step_s - elapsed_s (k = 0, 1, ...) that lie in [0, horizon_s],
// in seconds from now. A new candidate: over(rho), rho / kOccupancySamples apart. A committed
// merge's re-check keeps its decision's instants (elapsed_s since the decision), so that it agrees
// with the decision while the world goes as predicted, and only a real deviation aborts.
struct OccupancyInstants {
  double step_s = 0.0;
  double elapsed_s = 0.0;
  double horizon_s = 0.0;
  static OccupancyInstants over(double horizon_s) { return {horizon_s / kOccupancySamples, 0.0, horizon_s}; }
};
// Optional state shared by consecutive checks, which changes their cost, never their result:
// - per instant k, the lateral room below which the ego is not D_lon clear of some lane vehicle:
//   it depends on the ego's speed profile, the instants and the tracks, not on kappa, so the kappa
//   candidates of one v_e* share it (NaN: not computed yet; forget_ramp() for another profile);
// - the instant that blocked the last failed check, visited first by the next one: neighbouring
//   candidates mostly fail at the same instant.
// The extra lateral room an instant needs for the target lane's vehicles and for the other
// lanes' (-inf: none of them constrains it).
struct Blocking {
  double lane_m = -std::numeric_limits<double>::infinity();
  double beside_m = -std::numeric_limits<double>::infinity();
};
struct OccupancyMemo {
  std::array<Blocking, kOccupancySamples + 1> blocked_below_m;
  int last_blocked_k = -1;
  OccupancyMemo() { forget_ramp(); }
  void forget_ramp() { blocked_below_m.fill(Blocking{std::numeric_limits<double>::quiet_NaN(), 0.0}); }
};
bool occupancy_clear(const PlannerSetup& s, double ego_x_m, double ego_y_m, const Sigmoid& sig, const SpeedRamp& ego,
                     const OccupancyInstants& when, const GapTracks& tracks, double buffer_m,
                     OccupancyMemo* memo = nullptr,
                     double lateral_slack_m = 0.0);

}  // namespace mg
