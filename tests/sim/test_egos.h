// Ego dynamics shared by the simulator tests.
#pragma once

#include "core/scenario.h"

namespace mg::test {

// A soft neutral-steer ego (2000 kg, C_f l_f = C_r l_r): the scenario generator's boundary, where
// the steady-state sideslip per unit curvature is largest. Its state in the tests comes from
// corpus/cases/rcpp__ego_never_liable__sideslip__ego-4.json.
inline EgoDynamics soft_neutral_steer_ego() {
  EgoDynamics d;
  d.mass_kg = 2000.0;
  d.yaw_inertia_kgm2 = 3000.0;
  d.cg_to_front_m = 1.2;
  d.cg_to_rear_m = 1.4;
  d.cornering_front_npr = 67000.0;
  d.cornering_rear_npr = 67000.0 * 1.2 / 1.4;
  return d;
}

}  // namespace mg::test
