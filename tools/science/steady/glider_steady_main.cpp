// SPDX-License-Identifier: Apache-2.0
// glider-steady: steady glides of a vehicle file, forward (ballast and
// battery -> glide) and inverse (glide path and net buoyancy -> ballast and
// battery).
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "glider/cli/tool.hpp"
#include "glider/config/toml_document.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/units.hpp"

namespace {

using glider::rad_to_deg;

struct Report {
  std::string vehicle;
  std::string mode;
  double depth_m = 0.0;
  double density = 0.0;
  glider::model::SteadyGlide glide;
  double ballast_cc = 0.0;
  double battpos_in = 0.0;
  bool within_limits = true;
  std::string note;
};

nlohmann::ordered_json to_json(const Report& r) {
  nlohmann::ordered_json j;
  j["vehicle"] = r.vehicle;
  j["mode"] = r.mode;
  j["pitch_deg"] = rad_to_deg(r.glide.pitch_rad);
  j["angle_of_attack_deg"] = rad_to_deg(r.glide.alpha_rad);
  j["glide_path_deg"] = rad_to_deg(r.glide.glide_path_rad);
  j["speed_m_s"] = r.glide.speed_m_s;
  j["depth_rate_m_s"] = r.glide.depth_rate_m_s;
  j["horizontal_speed_m_s"] = r.glide.horizontal_speed_m_s;
  j["net_buoyancy_g"] = r.glide.net_buoyancy_kg * 1000.0;
  j["ballast_cc"] = r.ballast_cc;
  j["battpos_in"] = r.battpos_in;
  j["within_limits"] = r.within_limits;
  j["depth_m"] = r.depth_m;
  j["density_kg_m3"] = r.density;
  if (!r.note.empty()) j["note"] = r.note;
  return j;
}

void print_text(const Report& r) {
  std::printf("Steady glide of %s (%s; %.0f m, water %.1f kg/m^3)\n", r.vehicle.c_str(), r.mode.c_str(), r.depth_m,
              r.density);
  std::printf("  ballast            %+8.1f cc   (m_ballast_pumped)\n", r.ballast_cc);
  std::printf("  battery            %+8.3f in   (m_battpos)\n", r.battpos_in);
  std::printf("  net buoyancy       %+8.1f g    (+ heavy)\n", r.glide.net_buoyancy_kg * 1000.0);
  std::printf("  pitch              %+8.2f deg\n", rad_to_deg(r.glide.pitch_rad));
  std::printf("  angle of attack    %+8.2f deg\n", rad_to_deg(r.glide.alpha_rad));
  std::printf("  glide path         %+8.2f deg\n", rad_to_deg(r.glide.glide_path_rad));
  std::printf("  speed              %8.3f m/s\n", r.glide.speed_m_s);
  std::printf("  depth rate         %+8.3f m/s  (+ descending)\n", r.glide.depth_rate_m_s);
  std::printf("  horizontal speed   %8.3f m/s\n", r.glide.horizontal_speed_m_s);
  if (!r.within_limits) std::printf("  WARNING: %s\n", r.note.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-steady", "Steady glides of a glider vehicle model (forward and inverse)");
  std::string vehicle_path;
  double ballast_cc = NAN, battpos_in = NAN, glide_path_deg = NAN, net_buoyancy_g = NAN;
  double depth_m = 100.0;
  double density = NAN;
  bool json = false;
  tool.add_vehicle_option(vehicle_path);
  // Ranges: what any glider the model describes could be asked (a 50 kg
  // SLOCUM pumps +-500 cc, slides +-2 in); the vehicle's own limits are
  // checked after (a WARNING outside them).
  auto* ballast =
      tool.add_number("--ballast-cc", ballast_cc, {-5000.0, 5000.0, "cc"}, "pumped volume, cc (+ = more buoyant)");
  auto* battery =
      tool.add_number("--battpos-in", battpos_in, {-50.0, 50.0, "in"}, "battery position, in (+ = forward)");
  auto* path =
      tool.add_number("--glide-path-deg", glide_path_deg, {0.0, 90.0, "deg"}, "glide path angle magnitude, deg");
  auto* buoyancy = tool.add_number("--net-buoyancy-g", net_buoyancy_g, {-5000.0, 5000.0, "g"},
                                   "net buoyancy, g (+ heavy: descending)");
  tool.add_number("--depth-m", depth_m, {0.0, 11000.0, "m"}, "depth of the glide (compressibility)")
      ->capture_default_str();
  tool.add_number("--density", density, {900.0, 1100.0, "kg/m^3"},
                  "water density, kg/m^3 (default: the vehicle's trim density)");
  tool.add_json_flag(json);
  ballast->needs(battery);
  battery->needs(ballast);
  path->needs(buoyancy);
  buoyancy->needs(path);
  ballast->excludes(path);
  path->excludes(ballast);
  return tool.run(argc, argv, [&] {
    const bool forward = !std::isnan(ballast_cc);
    if (!forward && std::isnan(glide_path_deg)) {
      return tool.fail(glider::cli::kUsage,
                       "give either --ballast-cc and --battpos-in, or --glide-path-deg and --net-buoyancy-g");
    }

    const glider::model::VehicleParams vehicle = glider::model::load_vehicle_file(vehicle_path);
    if (std::isnan(density)) density = vehicle.trim_density_kg_m3;
    const glider::model::GliderDynamics dynamics(vehicle, glider::model::still_water(density));

    Report report;
    report.vehicle = vehicle.name;
    report.depth_m = depth_m;
    report.density = density;
    if (forward) {
      report.mode = "forward: ballast and battery given";
      glider::model::MassInputs masses;
      masses.pumped_volume_m3 = glider::cc_to_m3(ballast_cc);
      masses.battery_pos_m = glider::in_to_m(battpos_in);
      const auto result = glider::model::solve_equilibrium(dynamics, masses, depth_m);
      if (!result.glide) return tool.fail(glider::cli::kError, result.error);
      report.glide = *result.glide;
      report.ballast_cc = ballast_cc;
      report.battpos_in = battpos_in;
      const auto& v = vehicle;
      if (masses.pumped_volume_m3 < v.ballast.volume_min_m3 || masses.pumped_volume_m3 > v.ballast.volume_max_m3 ||
          masses.battery_pos_m < v.battery.travel_min_m || masses.battery_pos_m > v.battery.travel_max_m) {
        report.within_limits = false;
        report.note = "inputs outside the vehicle's pump range or slide travel";
      }
    } else {
      report.mode = "inverse: glide path and net buoyancy given";
      const auto result =
          glider::model::solve_trim(dynamics, std::abs(glide_path_deg), net_buoyancy_g / 1000.0, depth_m);
      if (!result.trim) return tool.fail(glider::cli::kError, result.error);
      report.glide = result.trim->glide;
      report.ballast_cc = glider::m3_to_cc(result.trim->pumped_volume_m3);
      report.battpos_in = glider::m_to_in(result.trim->battery_pos_m);
      report.within_limits = result.trim->within_limits;
      report.note = result.trim->note;
    }
    if (json) {
      std::printf("%s\n", to_json(report).dump().c_str());
    } else {
      print_text(report);
    }
    return static_cast<int>(glider::cli::kOk);
  });
}
