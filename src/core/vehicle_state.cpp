#include "core/vehicle_state.h"

#include <cmath>

namespace mg {

double VehicleState::road_vx_mps() const { return vx_mps * std::cos(yaw_rad) - vy_mps * std::sin(yaw_rad); }
double VehicleState::road_vy_mps() const { return vx_mps * std::sin(yaw_rad) + vy_mps * std::cos(yaw_rad); }

}  // namespace mg
