// SPDX-License-Identifier: Apache-2.0
#include "glider/model/vehicle.hpp"

#include <cmath>

namespace glider::model {

bool has_second_mass(const VehicleParams& v) { return v.second_mass.mass_kg > 0.0; }

bool has_wings(const VehicleParams& v) { return v.hydro.wing_area_m2 > 0.0; }

double dry_mass_kg(const VehicleParams& v) {
  return v.hull_mass_kg + v.offset.mass_kg + v.battery.mass_kg + v.second_mass.mass_kg;
}

double displaced_volume_m3(const VehicleParams& v) {
  return (dry_mass_kg(v) - v.buoyancy_offset_kg) / v.trim_density_kg_m3;
}

std::string validate(const VehicleParams& v) {
  if (!(v.hull_mass_kg > 0.0)) return "mass.hull_kg must be positive";
  if (!(v.hull_inertia_kg_m2 > 0.0)) return "mass.hull_inertia_kg_m2 must be positive";
  if (!(v.offset.mass_kg >= 0.0)) return "mass.offset_kg must not be negative";
  if (!(v.battery.mass_kg > 0.0)) return "battery.mass_kg must be positive";
  if (!(v.battery.travel_min_m < v.battery.travel_max_m)) return "battery travel: min must be below max";
  if (!(v.battery.rate_m_s > 0.0)) return "battery.rate_m_s must be positive";
  if (has_second_mass(v) &&
      !(v.second_mass.travel_min_m < v.second_mass.travel_max_m && v.second_mass.rate_m_s > 0.0)) {
    return "second_mass: need travel_min_m < travel_max_m and a positive rate";
  }
  if (!(v.hull_compressibility_per_pa >= 0.0 && v.hull_compressibility_per_pa < 1e-8)) {
    return "hull.compressibility_per_pa must be in [0, 1e-8)";
  }
  if (!(std::abs(v.hull_thermal_expansion_per_k) < 1e-3)) return "hull.thermal_expansion_per_k must be below 1e-3";
  if (!(v.heading.yaw_time_constant_s > 0.0)) return "heading.yaw_time_constant_s must be positive";
  if (!(v.heading.fin_max_rad > 0.0 && v.heading.fin_rate_rad_s > 0.0)) {
    return "heading.fin_max_rad and fin_rate_rad_s must be positive";
  }
  if (!(v.ballast.volume_min_m3 < v.ballast.volume_max_m3)) return "ballast volume: min must be below max";
  if (!(v.ballast.rate_m3_s > 0.0)) return "ballast.rate_m3_s must be positive";
  if (!(v.ballast.lag_s >= 0.0 && v.ballast.lag_s < 600.0)) return "ballast.lag_s must be in [0, 600)";
  if (!(v.added_mass_x_kg >= 0.0 && v.added_mass_z_kg >= 0.0 && v.added_inertia_kg_m2 >= 0.0)) {
    return "added masses and inertia must not be negative";
  }
  if (!(v.hull_diameter_m > 0.0)) return "hull.diameter_m must be positive";
  const Hydrodynamics& h = v.hydro;
  if (!(h.reference_area_m2 > 0.0)) return "hydrodynamics.reference_area_m2 must be positive";
  if (!(h.cd0 > 0.0)) return "hydrodynamics.cd0 must be positive";
  if (!(h.cd0_reynolds_exponent >= 0.0 && h.cd0_reynolds_exponent <= 0.5)) {
    return "hydrodynamics.cd0_reynolds_exponent must be in [0, 0.5]";
  }
  if (!(h.cd0_reference_speed_m_s > 0.0)) return "hydrodynamics.cd0_reference_speed_m_s must be positive";
  if (!(h.cmq_m2 <= 0.0)) return "hydrodynamics.cmq_m2 must not be positive (damping)";
  if (!(h.fit_valid_to_rad > 0.0 && h.crossflow_from_rad > h.fit_valid_to_rad)) {
    return "hydrodynamics: need 0 < fit_valid_to_rad < crossflow_from_rad";
  }
  if (has_wings(v) && !(h.wing_aspect_ratio > 0.0 && h.wing_oswald_efficiency > 0.0)) {
    return "hydrodynamics.wing_area_m2 given: wing_aspect_ratio and wing_oswald_efficiency must be positive";
  }
  if (!has_wings(v) && (h.wing_aspect_ratio != 0.0 || h.wing_sweep_rad != 0.0 || h.wing_oswald_efficiency != 0.0)) {
    return "hydrodynamics.wing_*: the wing keys need wing_area_m2";
  }
  if (!(v.trim_density_kg_m3 > 900.0 && v.trim_density_kg_m3 < 1100.0)) {
    return "buoyancy.trim_density_kg_m3 must be a water density (900..1100)";
  }
  if (!(displaced_volume_m3(v) > 0.0)) return "displaced volume must be positive";
  return "";
}

}  // namespace glider::model
