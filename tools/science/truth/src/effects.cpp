// SPDX-License-Identifier: Apache-2.0
#include "glider/truth/effects.hpp"

#include <cmath>
#include <stdexcept>

namespace glider::truth {

const std::vector<EffectSpec>& effect_specs() {
  static const std::vector<EffectSpec> specs{
      {"buoyancy_offset", "g", -500.0, 500.0, false, "mass less trim density x volume, added to the file's (+ heavy)"},
      {"drag_change", "ratio", 0.3, 5.0, false, "factor on C_D0"},
      {"hull_compressibility", "1/Pa", -1.5e-9, 1.5e-9, false, "added to the hull's compressibility"},
      {"thermal_expansion", "1/K", -3e-4, 3e-4, false, "hull volume per K, trimmed at the log's median temperature"},
      {"vertical_water_velocity", "m/s", -0.05, 0.05, false,
       "a steady vertical water velocity in a layer (+ down); the truth is its mean over the glides"},
      {"pitch_trim_offset", "in", -2.0, 2.0, false, "the battery sits this far forward of where m_battpos says"},
      {"pump_lag", "s", 0.0, 120.0, false, "first-order lag of the displaced volume behind m_ballast_pumped"},
      {"lift_change", "ratio", 0.3, 3.0, false, "factor on the lift slope (the wings' induced drag with it)"},
      {"depth_lag", "s", 0.0, 10.0, false, "first-order lag of the pressure sensor, added to its own"},
      {"fin_delay", "s", 0.0, 60.0, true, "dead time between c_fin and the servo moving"},
      {"fin_deadband", "rad", 0.0, 0.1, true, "a command within this of the fin's position is not followed"},
      {"yaw_delay", "s", 0.0, 60.0, true, "dead time between the fin and the yaw it drives"},
      {"fin_effectiveness", "ratio", 0.1, 10.0, true, "factor on the yaw rate per fin angle and speed"},
      {"roll_offset", "rad", -0.35, 0.35, true, "roll the logged m_roll does not show"},
      {"yaw_time_constant", "s", 0.05, 60.0, true, "the yaw's slow pole (the fast one is the truth's own)"},
      {"autopilot_gain", "rad/rad", 0.0, 5.0, true, "proportional gain flown (the log states its own)"},
      {"autopilot_integral", "1/s", -0.2, 0.2, true, "integral gain flown"},
      {"autopilot_dgain", "s", -30.0, 30.0, true, "heading-rate gain flown"},
      {"autopilot_delay", "s", 0.0, 60.0, true, "the autopilot reads the heading this late"},
      {"autopilot_deadband", "rad", 0.0, 0.2, true,
       "heading error below which (rate inside its deadband) the fin holds"},
  };
  return specs;
}

const EffectSpec* find_effect(const std::string& id) {
  for (const EffectSpec& s : effect_specs()) {
    if (id == s.id) return &s;
  }
  return nullptr;
}

std::pair<std::string, double> parse_effect(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) throw std::invalid_argument("--effect '" + text + "': expected ID=VALUE");
  const std::string id = text.substr(0, eq);
  const EffectSpec* spec = find_effect(id);
  if (spec == nullptr) {
    std::string known;
    for (const EffectSpec& s : effect_specs()) known += std::string(known.empty() ? "" : ", ") + s.id;
    throw std::invalid_argument("--effect '" + text + "': unknown effect '" + id + "' (known: " + known + ")");
  }
  double value = 0.0;
  std::size_t used = 0;
  try {
    value = std::stod(text.substr(eq + 1), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() - eq - 1 || !std::isfinite(value) || value < spec->min || value > spec->max) {
    throw std::invalid_argument("--effect '" + text + "': value of " + id + " must be a number in [" +
                                std::to_string(spec->min) + ", " + std::to_string(spec->max) + "] " + spec->unit);
  }
  return {id, value};
}

}  // namespace glider::truth
