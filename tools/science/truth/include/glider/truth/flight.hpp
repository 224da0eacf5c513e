// SPDX-License-Identifier: Apache-2.0
#pragma once
// A truth flight: a yo mission flown by the truth's own controllers (a
// bang-bang pump always; the battery either Slocum-like bang-bang - move by
// the estimated correction when the pitch error leaves a deadband, then
// wait - or a PI pitch controller), a Slocum-law heading autopilot through
// a fin servo with dead time and deadband, the dynamics of dynamics.hpp
// integrated by Dormand-Prince 5(4) between control cycles of 1-8 s, and
// the sensors of sensors.hpp. Everything not given is drawn from the seed.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "glider/truth/effects.hpp"
#include "glider/truth/vehicle.hpp"
#include "glider/truth/water.hpp"

namespace glider::truth {

enum class PitchControl { kBangBang, kPi };
const char* to_string(PitchControl c);

struct FlightRequest {
  std::string vehicle_path;  // a boards/ vehicle file (its published numbers)
  bool deep = false;         // dive range of the deeper variant
  Effects effects;
  std::uint64_t seed = 1;
  int yos = 6;
  // Drawn from the seed unless given:
  std::optional<PitchControl> control;
  std::optional<double> cycle_s, dive_to_m;
};

// One control cycle: what the sensors said, what was commanded, and the truth.
struct Sample {
  double time_s;
  double depth_m, pitch_rad, roll_rad, heading_rad, fin_rad, ballast_cc, battpos_in;  // measured
  double c_heading_rad, c_fin_rad, c_ballast_cc, c_battpos_in, c_pitch_rad;           // commanded (NaN: none)
  int depth_state, yo_count;
  double temperature_c, pressure_bar, density_kg_m3;  // the CTD (measured)
  // truth
  double true_depth_m, water_w_m_s, speed_m_s, alpha_rad, lat_m, lon_m;
};

struct FlightResult {
  std::vector<Sample> samples;
  Vehicle vehicle;  // as flown
  Water water;
  PitchControl control = PitchControl::kPi;
  double cycle_s = 4.0, dive_to_m = 0.0, climb_to_m = 0.0, pitch_target_rad = 0.0;
  double depth_sensor_lag_s = 0.0;
  // Autopilot: stated in the log's header / flown.
  double stated_gain = 1.5, stated_igain = 0.02, stated_dgain = -4.0, rate_deadband_rad_s = 0.0087;
  double flown_gain = 1.5, flown_igain = 0.02, flown_dgain = -4.0, flown_deadband_rad = 0.0, autopilot_delay_s = 0.0;
  double yaw_delay_s = 0.0, fin_effectiveness = 1.0, roll_offset_rad = 0.0;
  Effects truth;  // the hidden effects' true values as the log shows them (see effects.hpp)
  std::size_t steps_accepted = 0, steps_rejected = 0;
};

// Throws std::runtime_error when the flight cannot be flown (a stall: the
// vehicle never reaches its depths).
FlightResult fly(const FlightRequest& request);

}  // namespace glider::truth
