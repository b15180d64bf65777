// The potential field of RCPP eq. (3)-(5) along a candidate merge (docs/planner.md): the scenes
// at kFieldSamples + 1 instants of [0, duration_s], every other vehicle at other_x_at(o, t),
// sigma from the RSS distances at the decision instant. A timeline does not depend on the
// candidate path: one serves every candidate of a search.
#pragma once

#include <functional>
#include <vector>

#include "planner/planner.h"
#include "planner/potential_field.h"
#include "planner/sigmoid.h"

namespace mg {

inline constexpr int kFieldSamples = 16;  // time samples of the potential along a candidate

struct FieldTimeline {
  double duration_s = 0.0;
  std::vector<FieldScene> scenes;  // scenes[k] at t = duration_s k / kFieldSamples
};

FieldTimeline field_timeline(const WorldSnapshot& w, double duration_s,
                             const std::function<double(const ObservedVehicle&, double)>& other_x_at);

// Potential field cost of a candidate path: the mean over the timeline's instants of the
// potential at the ego, at ego_x_at(t) on the sigmoid.
template <class EgoXAt>
double field_cost(const RcppParams& p, const FieldTimeline& field, const Sigmoid& sig, EgoXAt ego_x_at) {
  double sum = 0.0;
  for (int k = 0; k <= kFieldSamples; ++k) {
    const double x = ego_x_at(field.duration_s * k / kFieldSamples);
    sum += field_potential(field.scenes[static_cast<std::size_t>(k)], p, x, sig.y_at_m(x));
  }
  return sum / (kFieldSamples + 1);
}

// A lower bound of field_cost for any candidate, in floating point: its sum with every term at
// field_potential_floor (each term is at least that, and each addition and the division are
// monotone), divided as field_cost divides.
double field_cost_floor(const RcppParams& p);

}  // namespace mg
