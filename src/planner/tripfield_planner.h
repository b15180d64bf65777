// Baseline: a local potential-field planner in the style of TriPField (Ji et al., IEEE T-ITS 2023),
// the comparison of the RCPP paper (spec §6). No public code exists; this is what was built
// (docs/planner.md): each cycle the path follows the descending lateral gradient of a field made of
// road marks (RCPP eq. 3), velocity-dependent elliptical Gaussian obstacle fields, and a
// target-lane attraction that grows toward the side lane's end; the speed is reduced by the
// obstacle field ahead. It has no RSS reasoning and no commitment, so it weaves and merges late.
#pragma once

#include <string>

#include "planner/planner.h"

namespace mg {

struct TripFieldCoefficients {
  double obstacle_gain = 10.0;           // peak of an obstacle field
  double headway_s = 1.0;                // ellipse half-length grows by v_o * headway_s
  double lateral_margin_m = 0.3;         // ellipse half-width beyond the half widths
  double lane_attraction = 0.2;          // target-lane attraction coefficient
  double end_urgency_length_m = 50.0;    // attraction grows as exp(-(end - X)/length)
  double end_urgency_gain = 4.0;
  double gradient_step = 0.5;            // lateral step per metre per unit gradient
  double max_slope = 0.08;               // |dY/dX| of the generated path
  double speed_field_gain = 0.3;         // v = v_cruise / (1 + gain * obstacle field ahead)
};

// Value of one elliptical, velocity-dependent obstacle field at (dx, dy) from the obstacle centre.
double tripfield_obstacle_potential(double dx_m, double dy_m, double obstacle_speed_mps, double length_sum_m,
                                    double width_sum_m, const TripFieldCoefficients& k);

class TripFieldPlanner : public Planner {
 public:
  std::string name() const override { return "tripfield"; }
  PlanOutput plan(const WorldSnapshot& w) override;

 private:
  TripFieldCoefficients k_;
};

}  // namespace mg
