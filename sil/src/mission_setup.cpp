// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/mission_setup.hpp"

#include <cmath>

#include "glider/model/steady_glide.hpp"
#include "glider/units.hpp"

namespace glider::sil {

fw::mission_file::MissionVehicle mission_vehicle(const model::VehicleParams& v, double max_working_depth_m) {
  fw::mission_file::MissionVehicle m;
  m.max_working_depth_m = max_working_depth_m;
  m.limits.ballast_min_cc = m3_to_cc(v.ballast.volume_min_m3);
  m.limits.ballast_max_cc = m3_to_cc(v.ballast.volume_max_m3);
  m.limits.battery_min_in = m_to_in(v.battery.travel_min_m);
  m.limits.battery_max_in = m_to_in(v.battery.travel_max_m);
  m.fin_max_rad = v.heading.fin_max_rad;
  m.fin_rate_rad_s = v.heading.fin_rate_rad_s;
  m.yaw_gain_per_m = v.heading.fin_yaw_gain_per_m;
  return m;
}

fw::app::VehicleSetup vehicle_setup(const model::VehicleParams& v, const fw::app::FittedDevices& fitted,
                                    double max_working_depth_m, bool flight_model_dr, double density_kg_m3) {
  fw::app::VehicleSetup setup;
  setup.source = "vehicle " + v.name;
  setup.vehicle = mission_vehicle(v, max_working_depth_m);
  setup.vehicle.drop_weight_fitted = fitted.drop_weight;
  setup.fin_delay_s = v.heading.fin_delay_s;
  setup.fitted = fitted;
  if (flight_model_dr) setup.flight_model_dr = flight_model_dead_reckoning(v, density_kg_m3);
  return setup;
}

fw::app::FittedDevices load_fitted_devices(const std::filesystem::path& vehicle_file) {
  return fw::app::read_fitted_devices(config::TomlDocument::load(vehicle_file), fw::app::FittedDevices{});
}

fw::DeadReckoningConfig flight_model_dead_reckoning(const model::VehicleParams& v, double density_kg_m3,
                                                    fw::DeadReckoningConfig dr) {
  dr.method = fw::DrMethod::kFlightModel;
  const model::PitchGlideSolver solver(v.hydro);
  for (int direction = 0; direction < 2; ++direction) {
    auto& table = direction == 0 ? dr.dive_alpha_rad : dr.climb_alpha_rad;
    const double sign = direction == 0 ? -1.0 : 1.0;  // dives nose down and heavy
    double fallback = dr.assumed_alpha_rad;
    // From steep to shallow, so a pitch without a glide takes its steeper neighbour.
    for (std::size_t k = table.size(); k-- > 0;) {
      const double pitch = sign * (dr.table_first_pitch_rad + static_cast<double>(k) * dr.table_step_rad);
      // The angle of attack of a steady glide depends on the pitch alone
      // (tan(path) = D/L); any net buoyancy of the right sign finds it.
      const model::SteadyGlideResult r = solver.solve(density_kg_m3, pitch, sign * -0.2);
      if (r.glide) fallback = std::fabs(r.glide->alpha_rad);
      table[k] = fallback;
    }
  }
  // Coasting through an inflection: surge momentum over the drag's linear
  // damping at the glide speed, tau = (m + m_f1) / (rho A C_D0 V).
  const model::SteadyGlideResult typical = solver.solve(density_kg_m3, -0.4363, 0.2);
  if (typical.glide) {
    const double damping = density_kg_m3 * v.hydro.reference_area_m2 * v.hydro.cd0 * typical.glide->speed_m_s;
    dr.coast_time_constant_s = (model::dry_mass_kg(v) + v.added_mass_x_kg) / damping;
  }
  return dr;
}

}  // namespace glider::sil
