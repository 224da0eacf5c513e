// SPDX-License-Identifier: Apache-2.0
#include "heading_replay.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "glider/firmware/mission_file/mission_loader.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"
#include "glider/slocum/log_loader.hpp"

namespace glider::heading_study {
namespace {

// The comet logs' flight-computer cycle is 4.3-4.5 s: the SIL runs its loop
// at 4 s, so the autopilot acts as seldom as the real one.
constexpr hal::Micros kSlocumCycleUs = 4'000'000;
// The SIL's turn from east onto the mission's north is not steady flight.
constexpr double kSilSkipS = 900.0;

// Flies the heading-hold mission; returns the log read back.
flightlog::FlightLog fly(const std::string& source, const model::VehicleParams& vehicle,
                         const fw::HeadingControlConfig& law, double heading_noise_rad, const std::string& log_path) {
  fw::FlightSoftwareConfig base;
  base.heading = law;
  const auto loaded = fw::mission_file::load_mission_file(source + "/boards/missions/heading_hold.mi",
                                                          sil::mission_vehicle(vehicle, 102.0), base);
  if (!loaded.config) throw std::runtime_error("heading_hold.mi: " + loaded.diagnostics.front().text());
  sil::ScenarioOptions options;
  options.period_us = kSlocumCycleUs;
  // The plant at the accuracy reference step (0.1 s), not the campaigns' 1 s:
  // a science replay compared with a real log. At 1 s comet-2016's swing period
  // came out 84 s instead of 88 s (real 109 s), which the 20 % check sits next to.
  options.integration_step_s = 0.1;
  options.noise.heading_rad = heading_noise_rad;
  options.log_path = log_path;
  const sil::ScenarioResult r = sil::run_scenario(vehicle, *loaded.config, options);
  if (!r.error.empty() || !r.completed) {
    throw std::runtime_error(log_path + ": " + (r.error.empty() ? "mission did not complete" : r.error));
  }
  return flightlog::read_flight_log(log_path);
}

// The yaw rate a SIL log leaves unexplained, by the same estimator and model
// as the real log's (the flown vehicle is the model: only the disturbance and
// the compass noise are left).
diagnose::UnexplainedYaw unexplained(const flightlog::FlightLog& log, const model::VehicleParams& vehicle) {
  const diagnose::HeadingTrack track = diagnose::prepare_heading_track(log, vehicle);
  return diagnose::unexplained_yaw(track, vehicle, diagnose::nominal_heading_values(vehicle, {}));
}

// Median speed through the water on the glides, by the heading track's
// estimate (the speed the identification's yaw per fin is measured at).
double median_glide_speed(const flightlog::FlightLog& log, const model::VehicleParams& vehicle) {
  const diagnose::HeadingTrack track = diagnose::prepare_heading_track(log, vehicle);
  std::vector<double> speeds;
  for (const double v : track.speed_m_s) {
    if (std::isfinite(v)) speeds.push_back(v);
  }
  if (speeds.empty()) return std::nan("");
  std::nth_element(speeds.begin(), speeds.begin() + static_cast<long>(speeds.size() / 2), speeds.end());
  return speeds[speeds.size() / 2];
}

// The yaw disturbance whose SIL flight leaves as much yaw rate unexplained,
// with an autocorrelation as long, as the real log: for each correlation
// time of a short list, its RMS scaled twice by the ratio of what is left
// beyond the compass noise's floor; the correlation time whose flight's
// autocorrelation length is closest to the real one's.
void calibrate_disturbance(const std::string& source, model::VehicleParams& flown, const fw::HeadingControlConfig& law,
                           const diagnose::HeadingDiagnosis& d, const std::string& stem) {
  flown.heading.yaw_disturbance_rad_s = 0.0;
  const double floor =
      unexplained(fly(source, flown, law, d.heading_noise_rad, stem + "_calibration.csv"), flown).rms_rad_s;
  const double wanted = d.unexplained_yaw_rate_rad_s;
  if (!(wanted > floor)) return;  // the compass noise explains it all
  double best_rms = 0.0, best_tau = 0.0, best_miss = 1e9;
  for (const double tau : {4.0, 8.0, 16.0, 32.0}) {
    flown.heading.yaw_disturbance_correlation_s = tau;
    double rms = std::sqrt(wanted * wanted - floor * floor);
    diagnose::UnexplainedYaw left;
    for (int iteration = 0; iteration < 3; ++iteration) {
      flown.heading.yaw_disturbance_rad_s = rms;
      left = unexplained(fly(source, flown, law, d.heading_noise_rad, stem + "_calibration.csv"), flown);
      const double excess = std::max(1e-9, left.rms_rad_s * left.rms_rad_s - floor * floor);
      rms *= std::sqrt((wanted * wanted - floor * floor) / excess);
    }
    const double miss = std::abs(left.correlation_s - d.unexplained_correlation_s);
    if (miss < best_miss) {
      best_miss = miss;
      best_rms = rms;
      best_tau = tau;
    }
  }
  flown.heading.yaw_disturbance_rad_s = best_rms;
  flown.heading.yaw_disturbance_correlation_s = best_tau;
}

}  // namespace

Replay replay_log(const std::string& source, const std::string& log_path, const std::string& nominal_vehicle,
                  const std::string& out_dir, const ReplayOptions& options) {
  std::vector<slocum::Warning> warnings;
  const flightlog::FlightLog log = slocum::load_flight_log({{log_path}, {}}, {}, &warnings);
  const model::VehicleParams nominal = model::load_vehicle_file(nominal_vehicle);
  Replay r;
  r.identified = diagnose::diagnose_heading(nominal, log);
  r.real = heading_metrics(log, 0.0);
  const diagnose::HeadingDiagnosis& d = r.identified;
  // The extended vehicle, with the whole loop's dead time at the fin (the
  // SIL's firmware reads the heading without the real autopilot's lag; for
  // the loop a lag is a lag wherever it sits).
  model::VehicleParams flown = diagnose::apply(nominal, d);
  r.loop_delay_s = d.delay_autopilot_s + d.delay_servo_s + d.delay_after_fin_s;
  flown.heading.fin_delay_s = r.loop_delay_s;
  fw::HeadingControlConfig identified;
  identified.law = fw::HeadingLaw::kSlocum;
  identified.gain = diagnose::at(d.values, diagnose::HeadingEffect::kAutopilotGain);
  identified.igain = diagnose::at(d.values, diagnose::HeadingEffect::kAutopilotIntegral);
  identified.dgain = diagnose::at(d.values, diagnose::HeadingEffect::kAutopilotDgain);
  identified.rate_deadband_rad_s = d.configured.rate_deadband_rad_s;
  identified.heading_deadband_rad = diagnose::at(d.values, diagnose::HeadingEffect::kAutopilotDeadband);
  const std::string stem = out_dir + "/replay_" + std::filesystem::path(log_path).stem().string();
  // The comet logs' glider flies slower than the nominal vehicle at the
  // same pitch and pumped volume, and the yaw per fin is V fin_gain: with
  // match_speed the replay flies the log's speed. Lift and drag scale together (the reference area), so the
  // angle of attack the identification assumed at the logged pitch (its
  // lift factor a_eff) stays; V scales as 1 / sqrt(area) at a fixed angle.
  r.log_speed_m_s = median_glide_speed(log, nominal);
  if (options.match_speed) {
    model::VehicleParams still = flown;
    still.heading.yaw_disturbance_rad_s = 0.0;
    const double nominal_speed = median_glide_speed(fly(source, still, identified, 0.0, stem + "_speed.csv"), still);
    r.nominal_speed_m_s = nominal_speed;
    if (std::isfinite(r.log_speed_m_s) && std::isfinite(nominal_speed) && r.log_speed_m_s > 0.0) {
      r.area_scale = (nominal_speed / r.log_speed_m_s) * (nominal_speed / r.log_speed_m_s);
      flown.hydro.reference_area_m2 *= r.area_scale;
    }
  }
  if (options.yaw_disturbance) calibrate_disturbance(source, flown, identified, d, stem);
  r.yaw_disturbance_rad_s = flown.heading.yaw_disturbance_rad_s;
  r.yaw_disturbance_correlation_s = flown.heading.yaw_disturbance_correlation_s;
  const flightlog::FlightLog identified_log =
      fly(source, flown, identified, d.heading_noise_rad, stem + "_identified.csv");
  r.sil_identified = heading_metrics(identified_log, kSilSkipS);
  r.sil_speed_m_s = median_glide_speed(identified_log, flown);
  if (!options.match_speed) r.nominal_speed_m_s = r.sil_speed_m_s;
  fw::HeadingControlConfig compensated;
  compensated.law = fw::HeadingLaw::kCompensated;
  compensated.delay_s = r.loop_delay_s;  // told the identified dead time
  r.sil_compensated =
      heading_metrics(fly(source, flown, compensated, d.heading_noise_rad, stem + "_compensated.csv"), kSilSkipS);
  return r;
}

}  // namespace glider::heading_study
