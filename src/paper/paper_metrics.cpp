#include "paper/paper_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "sim/single_track.h"

namespace mg {
namespace {

std::optional<double> first_time(const Trace& t, EventKind k) {
  for (const TraceEvent& e : t.events)
    if (e.kind == k) return e.time_s;
  return std::nullopt;
}

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

int count_sign_changes(const std::vector<double>& v, double deadband) {
  int changes = 0, last_sign = 0;
  for (double x : v) {
    const int sign = x > deadband ? 1 : (x < -deadband ? -1 : 0);
    if (sign == 0) continue;
    if (last_sign != 0 && sign != last_sign) ++changes;
    last_sign = sign;
  }
  return changes;
}

bool boxes_overlap(double x1, double y1, double yaw1, double l1, double w1, double x2, double y2, double yaw2,
                   double l2, double w2) {
  const std::array<double, 4> axes_yaw{yaw1, yaw1 + M_PI / 2, yaw2, yaw2 + M_PI / 2};
  const double dx = x2 - x1, dy = y2 - y1;
  // Half extent of a box projected on a unit axis at angle a.
  auto radius = [](double yaw, double l, double w, double a) {
    return 0.5 * l * std::abs(std::cos(yaw - a)) + 0.5 * w * std::abs(std::sin(yaw - a));
  };
  for (double a : axes_yaw) {
    const double dist = std::abs(dx * std::cos(a) + dy * std::sin(a));
    if (dist > radius(yaw1, l1, w1, a) + radius(yaw2, l2, w2, a)) return false;
  }
  return true;
}

PaperMetrics compute_paper_metrics(const Scenario& s, const Trace& t) {
  PaperMetrics m;
  m.merge_start_time_s = first_time(t, EventKind::kMergeStart);
  const std::optional<double> complete = first_time(t, EventKind::kMergeComplete);
  const std::optional<double> midpoint = first_time(t, EventKind::kMergeMidpoint);
  m.merged = complete.has_value();
  if (m.merged && m.merge_start_time_s) m.merge_time_s = *complete - *m.merge_start_time_s;

  constexpr double inf = std::numeric_limits<double>::infinity();
  m.sideslip_min_rad = m.yaw_min_rad = m.ego_speed_min_mps = m.obstacle_speed_min_mps = inf;
  m.sideslip_max_rad = m.yaw_max_rad = m.ego_speed_max_mps = -inf;
  std::vector<double> lateral_speed;
  double length = 0.0;
  for (std::size_t k = 0; k < t.steps.size(); ++k) {
    const TraceStep& step = t.steps[k];
    const VehicleState& e = step.ego;
    const double beta = sideslip_rad(e);
    m.sideslip_min_rad = std::min(m.sideslip_min_rad, beta);
    m.sideslip_max_rad = std::max(m.sideslip_max_rad, beta);
    m.yaw_min_rad = std::min(m.yaw_min_rad, e.yaw_rad);
    m.yaw_max_rad = std::max(m.yaw_max_rad, e.yaw_rad);
    m.ego_speed_min_mps = std::min(m.ego_speed_min_mps, e.vx_mps);
    m.ego_speed_max_mps = std::max(m.ego_speed_max_mps, e.vx_mps);
    lateral_speed.push_back(e.road_vy_mps());
    if (midpoint && !m.merge_x_m && step.time_s >= *midpoint) m.merge_x_m = e.x_m;
    if (k > 0 && m.merge_time_s && step.time_s > *m.merge_start_time_s && step.time_s <= *complete + 1e-9)
      length += std::hypot(e.x_m - t.steps[k - 1].ego.x_m, e.y_m - t.steps[k - 1].ego.y_m);
    for (std::size_t i = 0; i < step.others.size(); ++i) {
      const VehicleState& o = step.others[i];
      m.obstacle_speed_min_mps = std::min(m.obstacle_speed_min_mps, o.vx_mps);
      const VehicleSize& os = s.vehicles[i].size;
      if (boxes_overlap(e.x_m, e.y_m, e.yaw_rad, s.ego.size.length_m, s.ego.size.width_m, o.x_m, o.y_m, o.yaw_rad,
                        os.length_m, os.width_m))
        m.collision = true;
    }
  }
  if (m.merge_time_s) m.path_length_m = length;
  if (s.vehicles.empty()) m.obstacle_speed_min_mps = std::numeric_limits<double>::quiet_NaN();
  m.lateral_reversals = count_sign_changes(lateral_speed, kLateralReversalDeadbandMps);
  return m;
}

nlohmann::json paper_metrics_to_json(const PaperMetrics& m) {
  return {{"merged", m.merged},
          {"collision", m.collision},
          {"merge_start_time_s", or_null(m.merge_start_time_s)},
          {"merge_time_s", or_null(m.merge_time_s)},
          {"path_length_m", or_null(m.path_length_m)},
          {"merge_x_m", or_null(m.merge_x_m)},
          {"lateral_reversals", m.lateral_reversals},
          {"sideslip_min_rad", m.sideslip_min_rad},
          {"sideslip_max_rad", m.sideslip_max_rad},
          {"yaw_min_rad", m.yaw_min_rad},
          {"yaw_max_rad", m.yaw_max_rad},
          {"ego_speed_min_mps", m.ego_speed_min_mps},
          {"ego_speed_max_mps", m.ego_speed_max_mps},
          {"obstacle_speed_min_mps", finite_or_null(m.obstacle_speed_min_mps)}};
}

std::optional<double> reduction_pct(const std::optional<double>& baseline, const std::optional<double>& value) {
  if (!baseline || !value || *baseline <= 0.0) return std::nullopt;
  return 100.0 * (*baseline - *value) / *baseline;
}

}  // namespace mg
