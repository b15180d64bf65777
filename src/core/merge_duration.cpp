#include "core/merge_duration.h"

#include <algorithm>
#include <cmath>

#include "core/demand.h"

namespace mg {

double shortest_comfortable_merge_s(double width_m, double lat_accel_mps2) {
  MG_DEMAND(width_m > 0.0 && lat_accel_mps2 > 0.0);
  return 2.0 * std::log(49.0) / std::sqrt(6.0 * std::sqrt(3.0) * lat_accel_mps2 / width_m);
}

double merge_duration_base_s(double rho_m_s, double width_m, double lat_accel_mps2) {
  return std::max(rho_m_s, kShortestMergeFactor * shortest_comfortable_merge_s(width_m, lat_accel_mps2));
}

}  // namespace mg
