// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the flight application must know about the vehicle it flies, as data:
// actuator travel, fin limits, depth rating, dead-reckoning table and the
// devices fitted. On the target it comes from the board file ([vehicle]
// table, and the devices the board configures); in SIL it is derived from the
// vehicle file (sil/src/mission_setup.cpp). The firmware never calls the model.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/dead_reckoning.hpp"
#include "glider/firmware/heading_controller.hpp"
#include "glider/firmware/mission_file/mission_loader.hpp"

namespace glider::fw::app {

// The devices a vehicle carries. A device that is not fitted is given to the
// flight software as an absent stand-in (absent_devices.hpp), and a mission
// that needs it is refused before launch.
struct FittedDevices {
  bool drop_weight = false;   // emergency weight with a burn wire (released on abort)
  bool leak_detector = true;  // leak line (the leak abort)
  bool rudder = true;         // fin axis (heading control, waypoints)
  bool power_monitor = true;  // battery charge and voltage (the low-charge abort)
};

struct VehicleSetup {
  std::string source;  // the file it came from (messages name it)
  // Pump/slide travel, fin limit and rate, yaw gain, depth rating, drop weight:
  // what a Slocum mission is checked against.
  mission_file::MissionVehicle vehicle;
  double fin_delay_s = 0.0;  // heading predictor's dead time
  FittedDevices fitted;
  // kFlightModel dead reckoning (alpha tables and coast time constant), when known.
  std::optional<DeadReckoningConfig> flight_model_dr;
};

// "proportional", "slocum" or "compensated" (the heading autopilot's laws).
std::optional<HeadingLaw> heading_law_from_name(std::string_view name);

// `[fitted]` of a vehicle or board file: drop_weight, leak_detector, rudder,
// power_monitor (booleans; absent keys keep `defaults`).
FittedDevices read_fitted_devices(const config::TomlDocument& doc, const FittedDevices& defaults);

// The `[vehicle]` table of a target board file (boards/README.md):
// max_working_depth_m, ballast_min_cc, ballast_max_cc, battery_min_in,
// battery_max_in, fin_max_deg, fin_rate_deg_s, fin_delay_s, yaw_gain_per_m,
// and optionally dr_dive_alpha_deg / dr_climb_alpha_deg (61 entries from 10
// deg of pitch in 1 deg steps) with dr_coast_time_constant_s. Throws
// config::ConfigError with file:line for a bad value. `fitted` is the board's.
VehicleSetup read_vehicle_setup(const config::TomlDocument& doc, const FittedDevices& fitted);
// The numbers of the board file's [vehicle] table and their ranges (the
// bad-value test tries each, tests/unit/test_value_limits.cpp).
const std::vector<config::KeyRange>& vehicle_setup_limits();

}  // namespace glider::fw::app
