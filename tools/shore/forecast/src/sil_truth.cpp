// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/sil_truth.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

#include "glider/config/value_limits.hpp"
#include "glider/firmware/app/mission_setup.hpp"
#include "glider/forecast/forecast.hpp"
#include "glider/forecast/speed_term.hpp"
#include "glider/forecast/surfacing_history.hpp"
#include "glider/forecast/tidal_prior.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/portable_random.hpp"
#include "glider/sil/scenario.hpp"

namespace glider::forecast {
namespace fs = std::filesystem;

namespace {}

Truth fly_truth(const TruthOptions& o) {
  Truth truth;
  sil::PortableRandom draw(sil::derived_seed(o.seed, 0x7472757468ULL));
  model::VehicleParams vehicle;
  try {
    vehicle = model::load_vehicle_file(o.vehicle);
  } catch (const config::ConfigError& e) {
    throw std::runtime_error(e.what());
  }
  const fw::app::FittedDevices fitted = sil::load_fitted_devices(o.vehicle);
  fw::app::VehicleSetup setup =
      sil::vehicle_setup(vehicle, fitted, o.max_working_depth_m, false, vehicle.trim_density_kg_m3);
  setup.source = o.vehicle.string();
  const fw::app::PreparedMission prepared = fw::app::prepare_mission(o.mission, setup, {});
  if (!prepared.config) throw std::runtime_error(prepared.refusal);

  // The water: a uniform mean current and an M2 tide (a tidal ellipse, the
  // two components in quadrature by a drawn phase), the truth the glider
  // never sees. WaterColumn's oscillation has one phase for both
  // components, so the tide is rectilinear along a drawn direction.
  const double mean_speed = o.mean_current_max_m_s * draw.uniform();
  const double mean_dir = 2.0 * std::numbers::pi * draw.uniform();
  const double tide = o.tide_amplitude_max_m_s * draw.uniform();
  const double tide_dir = std::numbers::pi * draw.uniform();
  const double tide_phase = 2.0 * std::numbers::pi * draw.uniform();
  model::WaterSample water;
  water.density_kg_m3 = vehicle.trim_density_kg_m3;
  water.current_east_m_s = mean_speed * std::sin(mean_dir);
  water.current_north_m_s = mean_speed * std::cos(mean_dir);
  model::Oscillation oscillation;
  oscillation.period_s = kM2PeriodS;
  oscillation.phase_rad = tide_phase;
  oscillation.east_m_s = tide * std::sin(tide_dir);
  oscillation.north_m_s = tide * std::cos(tide_dir);
  // The true vehicle is not the file's.
  model::VehicleParams flown = vehicle;
  const double drag = o.drag_factor * std::exp(o.drag_sigma * draw.gaussian());
  model::scale_drag(flown.hydro, drag);
  flown.buoyancy_offset_kg += o.buoyancy_sigma_kg * draw.gaussian();
  const double sensor_scale = o.pitch_bias_max > 0.0 ? 1.0 + o.pitch_bias_max * (2.0 * draw.uniform() - 1.0) : 1.0;
  fw::FlightSoftwareConfig config = *prepared.config;
  config.dead_reckoning = biased_pitch_dead_reckoning(config.dead_reckoning, sensor_scale);
  if (o.servo_on_sensor && std::isnan(config.mission.dive_battpos_in) && std::isnan(config.mission.climb_battpos_in)) {
    // The servo holds sensor = scale x hull at the mission's pitch.
    config.mission.dive_pitch_rad /= sensor_scale;
    config.mission.climb_pitch_rad /= sensor_scale;
  }
  char text[360];
  std::snprintf(text, sizeof text,
                "seed %llu: mean current %.3f E %.3f N m/s, M2 tide %.3f m/s toward %.0f deg (phase %.0f deg), drag "
                "x%.3f, buoyancy %+.0f g, pitch sensor x%.3f",
                static_cast<unsigned long long>(o.seed), water.current_east_m_s, water.current_north_m_s, tide,
                tide_dir * 180.0 / std::numbers::pi, tide_phase * 180.0 / std::numbers::pi, drag,
                1000.0 * (flown.buoyancy_offset_kg - vehicle.buoyancy_offset_kg), sensor_scale);
  truth.description = text;
  // The true tide as a table (a cos(omega (t - launch) - phase) per component, tide_table.hpp).
  truth.tide.reference_utc_s = o.utc_launch_s;
  TideConstituent m2;
  m2.name = "M2";
  m2.period_s = kM2PeriodS;
  auto as_component = [&](double signed_amplitude) {
    // amplitude sin(x + phase) = amplitude cos(x - (90 deg - phase)); a negative amplitude is half a turn on.
    TideComponent c;
    c.amplitude_m_s = std::fabs(signed_amplitude);
    c.phase_deg = 90.0 - tide_phase * 180.0 / std::numbers::pi + (signed_amplitude < 0.0 ? 180.0 : 0.0);
    return c;
  };
  m2.east = as_component(oscillation.east_m_s);
  m2.north = as_component(oscillation.north_m_s);
  truth.tide.constituents.push_back(m2);

  sil::ScenarioOptions opt;
  opt.seed = o.seed;
  opt.environment = model::Environment{model::WaterColumn({model::ProfileNode{0.0, water}}, oscillation)};
  opt.peripherals.gps.launch = o.launch;
  opt.peripherals.gps.noise_m = o.gps_noise_m;
  opt.max_sim_time_s = 3.0 * 86400.0;
  const fw::LocalFrame frame(o.launch);
  bool under = false;
  TruthSurfacing pending;
  pending.surfaced_utc_s = o.utc_launch_s;
  pending.lat_deg = o.launch.lat_deg;
  pending.lon_deg = o.launch.lon_deg;
  opt.stop_when = [&](double t, const fw::FlightSoftware& flight, const model::Truth& now) {
    const fw::Navigator& nav = flight.navigator();
    if (flight.phase() == fw::Phase::kAbort) return true;  // a truth that aborts ends there
    if (truth.logged.empty() || t + o.utc_launch_s >= truth.logged.back()[0] + 4.0) {
      truth.logged.push_back({o.utc_launch_s + t, now.depth_m, sensor_scale * now.pitch_rad});
    }
    if (!under && !nav.at_surface()) {
      // Dived: the call before it is over; the fix it dived from is the DR's origin.
      under = true;
      pending.dive_utc_s = o.utc_launch_s + t;
      const fw::LatLon fix = nav.dr_position();
      pending.fix_lat_deg = fix.lat_deg;
      pending.fix_lon_deg = fix.lon_deg;
      pending.have_current = nav.have_current();
      pending.water_vx = nav.current_m_s().east_m;
      pending.water_vy = nav.current_m_s().north_m;
      truth.surfacings.push_back(pending);
      return false;
    }
    if (under && nav.at_surface()) {
      under = false;
      pending = TruthSurfacing{};
      pending.surfaced_utc_s = o.utc_launch_s + t;
      pending.mission_time_s = t;
      const fw::LatLon at = frame.to_global({now.east_m, now.north_m});
      pending.lat_deg = at.lat_deg;
      pending.lon_deg = at.lon_deg;
      const fw::LatLon dr = nav.dr_position();
      pending.have_dr = true;
      pending.dr_lat_deg = dr.lat_deg;
      pending.dr_lon_deg = dr.lon_deg;
      if (static_cast<int>(truth.surfacings.size()) > o.surfacings) return true;
    }
    if (flight.complete()) return true;
    return false;
  };
  const sil::ScenarioResult result = sil::run_scenario(flown, config, opt);
  if (!result.error.empty()) throw std::runtime_error("truth flight: " + result.error);
  // The last surfacing (no dive after it): the fix is where it is.
  if (!under && truth.surfacings.size() <= static_cast<std::size_t>(o.surfacings) && pending.have_dr) {
    pending.dive_utc_s = pending.surfaced_utc_s + 60.0;
    pending.fix_lat_deg = pending.lat_deg;
    pending.fix_lon_deg = pending.lon_deg;
    truth.surfacings.push_back(pending);
  }
  return truth;
}

void write_glider_folder(const Truth& truth, const TruthOptions& o, const std::string& glider, std::size_t upto,
                         const fs::path& dir) {
  fs::create_directories(dir / "logs");
  fs::create_directories(dir / "mission" / "missions");
  fs::create_directories(dir / "mission" / "mafiles");
  fs::copy_file(o.mission, dir / "mission" / "missions" / o.mission.filename(), fs::copy_options::overwrite_existing);
  fs::path mafiles = o.mission.parent_path() / "mafiles";
  if (!fs::is_directory(mafiles)) mafiles = o.mission.parent_path() / ".." / "mafiles";
  if (fs::is_directory(mafiles)) {
    for (const fs::directory_entry& e : fs::directory_iterator(mafiles)) {
      if (e.path().extension() == ".ma") {
        fs::copy_file(e.path(), dir / "mission" / "mafiles" / e.path().filename(),
                      fs::copy_options::overwrite_existing);
      }
    }
  }
  for (std::size_t i = 0; i <= upto && i < truth.surfacings.size(); ++i) {
    const TruthSurfacing& s = truth.surfacings[i];
    nlohmann::json event{{"schema", "glider-shore-surfacing/1"},
                         {"glider", glider},
                         {"vehicle_name", glider},
                         {"call_start_utc", format_utc(s.surfaced_utc_s)},
                         {"call_end_utc", format_utc(s.dive_utc_s)},
                         {"glider_time", {{"mission_time_s", s.mission_time_s}}},
                         {"mission", {{"name", o.mission.filename().string()}}},
                         {"gps", {{"kind", "gps"}, {"lat_deg", s.fix_lat_deg}, {"lon_deg", s.fix_lon_deg}}}};
    if (s.have_dr) event["dr"] = {{"kind", "dr"}, {"lat_deg", s.dr_lat_deg}, {"lon_deg", s.dr_lon_deg}};
    nlohmann::json sensors = nlohmann::json::array();
    if (s.have_current) {
      sensors.push_back({{"name", "m_water_vx"}, {"unit", "m/s"}, {"value", s.water_vx}});
      sensors.push_back({{"name", "m_water_vy"}, {"unit", "m/s"}, {"value", s.water_vy}});
    }
    event["sensors"] = sensors;
    char name[64];
    std::snprintf(name, sizeof name, "%s_%04zu.surfacing.json", format_utc(s.surfaced_utc_s).substr(0, 10).c_str(),
                  i + 1);
    write_atomically(dir / "logs" / name, event.dump(2) + "\n");
  }
  if (upto < truth.surfacings.size()) {
    const double until = truth.surfacings[upto].surfaced_utc_s;
    std::string csv = "m_present_time,m_depth,m_pitch\n";
    char row[96];
    for (const auto& [t, depth, pitch] : truth.logged) {
      if (t < until - 86400.0 || t > until) continue;
      std::snprintf(row, sizeof row, "%.1f,%.3f,%.5f\n", t, depth, pitch);
      csv += row;
    }
    write_atomically(dir / "from-glider" / (glider + ".csv"), csv);
  }
}

}  // namespace glider::forecast
