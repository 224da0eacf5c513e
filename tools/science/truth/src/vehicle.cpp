// SPDX-License-Identifier: Apache-2.0
#include "glider/truth/vehicle.hpp"

#include <cmath>
#include <numbers>

#include "glider/config/toml_document.hpp"

namespace glider::truth {

Vehicle load_vehicle(const std::string& path) {
  const config::TomlDocument f = config::TomlDocument::load(path);
  Vehicle v;
  v.name = path.substr(path.find_last_of('/') + 1);
  v.hull_kg = f.number("mass.hull_kg", {0.0, 1000.0, "kg"});
  v.hull_inertia_kg_m2 = f.number("mass.hull_inertia_kg_m2", {0.0, 1000.0, "kg m^2"});
  v.offset_kg = f.number("mass.offset_kg", {0.0, 1000.0, "kg"});
  v.offset_x_m = f.number("mass.offset_x_m", {-2.0, 2.0, "m"});
  v.offset_z_m = f.number("mass.offset_z_m", {-1.0, 1.0, "m"});
  v.battery_kg = f.number("battery.mass_kg", {0.0, 100.0, "kg"});
  v.battery_x_at_zero_m = f.number("battery.x_at_zero_m", {-2.0, 2.0, "m"});
  v.battery_z_m = f.number("battery.z_m", {-1.0, 1.0, "m"});
  v.battery_min_m = f.number("battery.travel_min_m", {-1.0, 1.0, "m"});
  v.battery_max_m = f.number("battery.travel_max_m", {-1.0, 1.0, "m"});
  v.battery_rate_m_s = f.number("battery.rate_m_s", {1e-5, 1.0, "m/s"});
  v.ballast_x_m = f.number("ballast.x_m", {-2.0, 2.0, "m"});
  v.ballast_min_m3 = f.number("ballast.volume_min_m3", {-0.01, 0.0, "m^3"});
  v.ballast_max_m3 = f.number("ballast.volume_max_m3", {0.0, 0.01, "m^3"});
  v.pump_rate_m3_s = f.number("ballast.rate_m3_s", {1e-7, 1e-2, "m^3/s"});
  v.pump_lag_s = f.number_or("ballast.lag_s", 0.0, {0.0, 600.0, "s"});
  v.added_x_kg = f.number("added_mass.x_kg", {0.0, 1000.0, "kg"});
  v.added_z_kg = f.number("added_mass.z_kg", {0.0, 1000.0, "kg"});
  v.added_inertia_kg_m2 = f.number("added_mass.inertia_kg_m2", {0.0, 1000.0, "kg m^2"});
  v.hull_compressibility_per_pa = f.number_or("hull.compressibility_per_pa", 0.0, {-1e-8, 1e-8, "1/Pa"});
  v.thermal_expansion_per_k = f.number_or("hull.thermal_expansion_per_k", 0.0, {-1e-3, 1e-3, "1/K"});
  v.reference_temperature_c = f.number_or("hull.reference_temperature_c", 10.0, {-5.0, 40.0, "degC"});
  v.trim_density_kg_m3 = f.number("buoyancy.trim_density_kg_m3", {990.0, 1060.0, "kg/m^3"});
  v.buoyancy_offset_kg = f.number_or("buoyancy.offset_kg", 0.0, {-5.0, 5.0, "kg"});

  Hydro& h = v.hydro;
  h.area_m2 = f.number("hydrodynamics.reference_area_m2", {1e-4, 10.0, "m^2"});
  h.cl0 = f.number_or("hydrodynamics.cl0", 0.0, {-5.0, 5.0, "-"});
  h.cl_alpha = f.number("hydrodynamics.cl_alpha", {0.0, 100.0, "1/rad"});
  h.cl_alpha_abs_alpha = f.number_or("hydrodynamics.cl_alpha_abs_alpha", 0.0, {-100.0, 100.0, "1/rad^2"});
  h.cd0 = f.number("hydrodynamics.cd0", {0.0, 10.0, "-"});
  h.cd_alpha2 = f.number("hydrodynamics.cd_alpha2", {0.0, 1000.0, "1/rad^2"});
  h.cm0_m = f.number_or("hydrodynamics.cm0_m", 0.0, {-10.0, 10.0, "m"});
  h.cm_alpha_m = f.number("hydrodynamics.cm_alpha_m", {-100.0, 100.0, "m/rad"});
  h.cmq_m2 = f.number_or("hydrodynamics.cmq_m2", 0.0, {-100.0, 0.0, "m^2"});
  h.cn90 = f.number_or("hydrodynamics.crossflow_cn90", 1.0, {0.0, 100.0, "-"});
  h.fit_valid_to_rad = f.number_or("hydrodynamics.fit_valid_to_rad", 0.17, {0.01, 1.5, "rad"});
  h.crossflow_from_rad = f.number_or("hydrodynamics.crossflow_from_rad", 0.44, {0.02, 1.57, "rad"});
  // Wings by their planform (the lifting-line slope and the induced drag
  // of an elliptic-like loading with Oswald's e), referred to the area.
  const double wing_area = f.number_or("hydrodynamics.wing_area_m2", 0.0, {0.0, 10.0, "m^2"});
  if (wing_area > 0.0) {
    const double ar = f.number("hydrodynamics.wing_aspect_ratio", {0.5, 30.0, "-"});
    const double sweep = f.number_or("hydrodynamics.wing_sweep_rad", 0.0, {0.0, 1.4, "rad"});
    const double e = f.number_or("hydrodynamics.wing_oswald_efficiency", 0.8, {0.1, 1.0, "-"});
    const double tan_sweep = std::tan(sweep);
    const double a_w = 2.0 * std::numbers::pi * ar / (2.0 + std::sqrt(ar * ar * (1.0 + tan_sweep * tan_sweep) + 4.0));
    const double scale = wing_area / h.area_m2;
    const double wing_lift = a_w * scale;
    h.wing_induced_cd_alpha2 = a_w * a_w / (std::numbers::pi * e * ar) * scale;
    h.wing_lift_share = wing_lift / (h.cl_alpha + wing_lift);
    h.cl_alpha += wing_lift;
    h.cd_alpha2 += h.wing_induced_cd_alpha2;
  }
  HeadingParams& hd = v.heading;
  hd.fin_yaw_gain_per_m = f.number_or("heading.fin_yaw_gain_per_m", hd.fin_yaw_gain_per_m, {-10.0, 10.0, "1/m"});
  hd.roll_yaw_gain_per_m = f.number_or("heading.roll_yaw_gain_per_m", hd.roll_yaw_gain_per_m, {-10.0, 10.0, "1/m"});
  hd.yaw_time_constant_s = f.number_or("heading.yaw_time_constant_s", hd.yaw_time_constant_s, {0.05, 60.0, "s"});
  hd.roll_rad = f.number_or("heading.roll_offset_rad", 0.0, {-0.6, 0.6, "rad"});
  hd.fin_max_rad = f.number_or("heading.fin_max_rad", hd.fin_max_rad, {0.01, 1.0, "rad"});
  hd.fin_rate_rad_s = f.number_or("heading.fin_rate_rad_s", hd.fin_rate_rad_s, {0.001, 10.0, "rad/s"});
  hd.fin_delay_s = f.number_or("heading.fin_delay_s", 0.0, {0.0, 60.0, "s"});
  hd.fin_deadband_rad = f.number_or("heading.fin_deadband_rad", 0.0, {0.0, 0.2, "rad"});
  return v;
}

}  // namespace glider::truth
