// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/app/vehicle_setup.hpp"

#include <cmath>
#include <string>

#include "glider/units.hpp"

namespace glider::fw::app {
namespace {

// The [vehicle] table's numbers and their ranges (vehicle_setup_limits()).
const std::vector<config::KeyRange>& limits() {
  static const std::vector<config::KeyRange> table{
      {"vehicle.max_working_depth_m", {1.0, 11000.0, "m"}},
      {"vehicle.ballast_min_cc", {-5000.0, -1.0, "cc"}},
      {"vehicle.ballast_max_cc", {1.0, 5000.0, "cc"}},
      {"vehicle.battery_min_in", {-10.0, 10.0, "in"}},
      {"vehicle.battery_max_in", {-10.0, 10.0, "in"}},
      {"vehicle.fin_max_deg", {0.5, 45.0, "deg"}},
      {"vehicle.fin_rate_deg_s", {0.1, 180.0, "deg/s"}},
      {"vehicle.yaw_gain_per_m", {0.0, 100.0, "1/m"}},
      {"vehicle.fin_delay_s", {0.0, 60.0, "s"}},
      {"vehicle.dr_coast_time_constant_s", {0.1, 3600.0, "s"}},
  };
  return table;
}

// A finite number within the key's range; the refusal names file:line, key, value and range.
double in_range(const config::TomlDocument& doc, const char* key, double fallback) {
  return doc.number_or(key, fallback, config::range_of(limits(), key));
}

void read_alpha_table(const config::TomlDocument& doc, const char* key,
                      std::array<double, DeadReckoningConfig::kTableSize>& table) {
  const std::vector<double> degrees = doc.numbers_or_empty(key);
  if (degrees.size() != table.size()) {
    doc.fail(key, "needs " + std::to_string(table.size()) + " angles of attack (deg, pitch 10..70 deg)");
  }
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (!(degrees[i] >= 0.0 && degrees[i] <= 30.0)) doc.fail(key, "angles of attack must be within [0, 30] deg");
    table[i] = deg_to_rad(degrees[i]);
  }
}

}  // namespace

const std::vector<config::KeyRange>& vehicle_setup_limits() { return limits(); }

std::optional<HeadingLaw> heading_law_from_name(std::string_view name) {
  if (name == "proportional") return HeadingLaw::kProportional;
  if (name == "slocum") return HeadingLaw::kSlocum;
  if (name == "compensated") return HeadingLaw::kCompensated;
  return std::nullopt;
}

FittedDevices read_fitted_devices(const config::TomlDocument& doc, const FittedDevices& defaults) {
  FittedDevices f;
  f.drop_weight = doc.boolean_or("fitted.drop_weight", defaults.drop_weight);
  f.leak_detector = doc.boolean_or("fitted.leak_detector", defaults.leak_detector);
  f.rudder = doc.boolean_or("fitted.rudder", defaults.rudder);
  f.power_monitor = doc.boolean_or("fitted.power_monitor", defaults.power_monitor);
  doc.reject_unknown_keys_in("fitted");  // a misspelt device would silently keep its default
  return f;
}

VehicleSetup read_vehicle_setup(const config::TomlDocument& doc, const FittedDevices& fitted) {
  VehicleSetup s;
  s.source = doc.source();
  s.fitted = fitted;
  mission_file::MissionVehicle& v = s.vehicle;
  v.max_working_depth_m = in_range(doc, "vehicle.max_working_depth_m", v.max_working_depth_m);
  ActuatorLimits& l = v.limits;
  l.ballast_min_cc = in_range(doc, "vehicle.ballast_min_cc", l.ballast_min_cc);
  l.ballast_max_cc = in_range(doc, "vehicle.ballast_max_cc", l.ballast_max_cc);
  l.battery_min_in = in_range(doc, "vehicle.battery_min_in", l.battery_min_in);
  l.battery_max_in = in_range(doc, "vehicle.battery_max_in", l.battery_max_in);
  if (!(l.battery_min_in < l.battery_max_in)) doc.fail("vehicle.battery_max_in", "must be above battery_min_in");
  v.fin_max_rad = deg_to_rad(in_range(doc, "vehicle.fin_max_deg", rad_to_deg(v.fin_max_rad)));
  v.fin_rate_rad_s = deg_to_rad(in_range(doc, "vehicle.fin_rate_deg_s", rad_to_deg(v.fin_rate_rad_s)));
  v.yaw_gain_per_m = in_range(doc, "vehicle.yaw_gain_per_m", v.yaw_gain_per_m);
  s.fin_delay_s = in_range(doc, "vehicle.fin_delay_s", s.fin_delay_s);
  v.drop_weight_fitted = fitted.drop_weight;
  const bool dive_table = doc.has("vehicle.dr_dive_alpha_deg");
  if (dive_table || doc.has("vehicle.dr_climb_alpha_deg")) {
    DeadReckoningConfig dr;
    dr.method = DrMethod::kFlightModel;
    read_alpha_table(doc, "vehicle.dr_dive_alpha_deg", dr.dive_alpha_rad);
    read_alpha_table(doc, "vehicle.dr_climb_alpha_deg", dr.climb_alpha_rad);
    dr.coast_time_constant_s = in_range(doc, "vehicle.dr_coast_time_constant_s", dr.coast_time_constant_s);
    s.flight_model_dr = dr;
  }
  return s;
}

}  // namespace glider::fw::app
