// SPDX-License-Identifier: Apache-2.0
#pragma once
// What only a flight model can add to a glider's data (docs/netcdf.md,
// "Flight-model products"): for every sample of a dive or climb, the steady
// glide at the logged pitch with the net buoyancy of the logged pump volume
// (model/steady_glide.hpp's PitchGlideSolver, the approach of the diagnosis's
// steady model), and from it the water's vertical velocity and the
// depth-averaged current of each dive between two GPS fixes.
#include <string>
#include <utility>
#include <vector>

#include "glider/model/vehicle.hpp"
#include "glider/netcdf/trajectory.hpp"

namespace glider::netcdf {

struct CurrentEstimate {
  std::size_t first = 0, last = 0;  // samples from the fix before the dive to the fix after it
  double start_s = 0.0, end_s = 0.0;
  double latitude = 0.0, longitude = 0.0;  // mean of the two fixes
  double east_m_s = 0.0, north_m_s = 0.0;
  double uncertainty_m_s = 0.0;  // one standard deviation, see the .cpp for its terms
};

struct FlightProducts {
  // Per sample; NaN outside dives and climbs or where the model has no glide.
  std::vector<double> speed_m_s;        // through the water, along the path
  std::vector<double> alpha_deg;        // angle of attack
  std::vector<double> glide_angle_deg;  // path below (-) or above (+) the horizontal
  std::vector<double> glider_w_m_s;     // the model's vertical velocity, + up
  std::vector<double> measured_w_m_s;   // -d(depth)/dt, + up (line fit over +-5 s)
  std::vector<double> water_w_m_s;      // measured minus the glider's, + up
  std::vector<double> current_east_m_s, current_north_m_s, current_uncertainty_m_s;  // per sample of a dive
  std::vector<CurrentEstimate> currents;                                             // one per dive between two fixes
  std::vector<std::pair<std::string, double>> parameters;  // the model's parameters, written as attributes
  std::string vehicle_name;
};

// Assumptions of the current's uncertainty (written with it).
constexpr double kGpsFixErrorM = 10.0;        // one fix, one standard deviation
constexpr double kSpeedRelativeError = 0.10;  // the model's horizontal speed

FlightProducts compute_flight_products(const Trajectory& t, const model::VehicleParams& vehicle);

}  // namespace glider::netcdf
