// SPDX-License-Identifier: Apache-2.0
#include "heading_replay.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "glider/firmware/app/mission_setup.hpp"
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
                         const model::Environment& water, const fw::HeadingControlConfig& law, double heading_noise_rad,
                         const std::string& log_path, const ReplayOptions& run) {
  // The mission as glider-sil prepares it (the flight application's one mission entry), its
  // heading autopilot starting from the loop identified on the real log, the replay's subject.
  const fw::app::VehicleSetup setup =
      sil::vehicle_setup(vehicle, {}, 102.0, false, water.water.at(0.0, 0.0).density_kg_m3);
  fw::app::MissionOptions mission_options;
  mission_options.heading = law;
  const fw::app::PreparedMission prepared =
      fw::app::prepare_mission(source + "/boards/missions/heading_hold.mi", setup, mission_options);
  if (!prepared.config) {
    throw std::runtime_error("heading_hold.mi: " + fw::app::mission_messages(prepared, true).front());
  }
  sil::ScenarioOptions options;
  options.period_us = kSlocumCycleUs;
  options.environment = water;
  options.seed = run.seed;
  options.integration_step_s = run.integration_step_s;
  options.noise.heading_rad = heading_noise_rad;
  options.log_path = log_path;
  const sil::ScenarioResult r = sil::run_scenario(vehicle, *prepared.config, options);
  if (!r.error.empty() || !r.completed) {
    throw std::runtime_error(log_path + ": " + (r.error.empty() ? "mission did not complete" : r.error));
  }
  return flightlog::read_flight_log(log_path);
}

// The yaw rate a SIL log leaves unexplained, by the same estimator and model
// as the real log's (the flown vehicle is the model: only the disturbance and
// the compass noise are left).
// `shear`: the profile the SIL flew (nullptr: still water).
diagnose::UnexplainedYaw unexplained(const flightlog::FlightLog& log, const model::VehicleParams& vehicle,
                                     const diagnose::ShearProfile* shear) {
  const diagnose::HeadingTrack track = diagnose::prepare_heading_track(log, vehicle);
  return diagnose::unexplained_yaw(track, vehicle, diagnose::nominal_heading_values(vehicle, {}), shear);
}

// Median speed through the water on the dives and on the climbs, by the
// heading track's estimate (the speed the identification's yaw per fin is
// measured at).
GlideSpeeds glide_speeds(const flightlog::FlightLog& log, const model::VehicleParams& vehicle) {
  const diagnose::HeadingTrack track = diagnose::prepare_heading_track(log, vehicle);
  std::vector<double> dives, climbs;
  for (std::size_t i = 0; i < track.size(); ++i) {
    if (!std::isfinite(track.speed_m_s[i])) continue;
    if (track.phase[i] == flightlog::Phase::kDive) dives.push_back(track.speed_m_s[i]);
    if (track.phase[i] == flightlog::Phase::kClimb) climbs.push_back(track.speed_m_s[i]);
  }
  auto median = [](std::vector<double>& v) {
    if (v.empty()) return std::nan("");
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  return {median(dives), median(climbs)};
}

// The yaw disturbance whose SIL flight leaves as much yaw rate unexplained,
// with an autocorrelation as long, as the real log: for each correlation
// time of a short list, its RMS scaled twice by the ratio of what is left
// beyond the compass noise's floor; the correlation time whose flight's
// autocorrelation length is closest to the real one's.
void calibrate_disturbance(const std::string& source, model::VehicleParams& flown, const model::Environment& water,
                           const fw::HeadingControlConfig& law, const diagnose::HeadingDiagnosis& d,
                           const std::string& stem, const ReplayOptions& run, const diagnose::UnexplainedYaw& target,
                           const diagnose::ShearProfile* shear) {
  flown.heading.yaw_disturbance_rad_s = 0.0;
  const double floor =
      unexplained(fly(source, flown, water, law, d.heading_noise_rad, stem + "_calibration.csv", run), flown, shear)
          .rms_rad_s;
  const double wanted = target.rms_rad_s;
  if (!(wanted > floor)) return;  // the compass noise explains it all
  double best_rms = 0.0, best_tau = 0.0, best_miss = 1e9;
  for (const double tau : {4.0, 8.0, 16.0, 32.0}) {
    flown.heading.yaw_disturbance_correlation_s = tau;
    double rms = std::sqrt(wanted * wanted - floor * floor);
    diagnose::UnexplainedYaw left;
    for (int iteration = 0; iteration < 3; ++iteration) {
      flown.heading.yaw_disturbance_rad_s = rms;
      left = unexplained(fly(source, flown, water, law, d.heading_noise_rad, stem + "_calibration.csv", run), flown,
                         shear);
      const double excess = std::max(1e-9, left.rms_rad_s * left.rms_rad_s - floor * floor);
      rms *= std::sqrt((wanted * wanted - floor * floor) / excess);
    }
    const double miss = std::abs(left.correlation_s - target.correlation_s);
    if (miss < best_miss) {
      best_miss = miss;
      best_rms = rms;
      best_tau = tau;
    }
  }
  flown.heading.yaw_disturbance_rad_s = best_rms;
  flown.heading.yaw_disturbance_correlation_s = best_tau;
}

// The water of the replay: the identified shear across the heading as an
// east current (the heading-hold mission flies north: starboard is east),
// zero at the surface, piecewise linear between the fitted bins' edges.
model::Environment sheared_water(const diagnose::ShearProfile& shear) {
  model::Environment water;
  std::vector<model::ProfileNode> nodes;
  double current = 0.0;
  nodes.push_back({0.0, {}});
  for (const diagnose::ShearBin& b : shear.bins) {
    current += (b.fitted ? b.shear_per_s : 0.0) * (b.to_m - b.from_m);
    model::ProfileNode node;
    node.depth_m = b.to_m;
    node.water.current_east_m_s = current;
    nodes.push_back(node);
  }
  water.water = model::WaterColumn(nodes, {});
  return water;
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
  // The shear flown (and left out of the yaw the disturbance must explain): the replayed log's, or another's.
  diagnose::ShearProfile shear_flown = d.current_shear;
  if (!options.water_log.empty()) {
    shear_flown = diagnose::diagnose_heading(nominal, slocum::load_flight_log({{options.water_log}, {}}, {}, &warnings))
                      .current_shear;
  }
  const model::Environment water = options.current_shear ? sheared_water(shear_flown) : model::Environment{};
  // The comet logs' glider flies slower than the nominal vehicle at the
  // same pitch and pumped volume, and faster climbing than diving; the yaw
  // per fin is V fin_gain, and the time spent in each layer of a sheared
  // current is 1 / w. With match_speed the replay flies the log's speeds:
  // lift and drag scaled together (the reference area: the angle of attack
  // the identification assumed at the logged pitch, its lift factor a_eff,
  // stays; V^2 ~ 1 / area) and a buoyancy offset b (V^2 ~ B0 +- b on dives
  // and climbs, B0 the pumped volume's buoyancy).
  r.log_speed = glide_speeds(log, nominal);
  r.nominal_speed = glide_speeds(fly(source, flown, water, identified, 0.0, stem + "_speed.csv", options), flown);
  const GlideSpeeds& want = r.log_speed;
  const GlideSpeeds& have = r.nominal_speed;
  if (options.match_speed && std::isfinite(want.dive + want.climb + have.dive + have.climb)) {
    const double want_sum = want.dive * want.dive + want.climb * want.climb;
    const double have_sum = have.dive * have.dive + have.climb * have.climb;
    const double b0 = -flown.ballast.volume_min_m3 * flown.trim_density_kg_m3;
    r.area_scale = have_sum / want_sum;
    r.buoyancy_offset_kg = b0 * ((want.dive * want.dive - want.climb * want.climb) / want_sum -
                                 (have.dive * have.dive - have.climb * have.climb) / have_sum);
    flown.hydro.reference_area_m2 *= r.area_scale;
    flown.buoyancy_offset_kg += r.buoyancy_offset_kg;
  }
  if (options.yaw_disturbance) {
    // What the real log leaves: after the shear when the replay flies it,
    // else all the extended yaw model leaves.
    const diagnose::ShearProfile* shear = options.current_shear ? &d.current_shear : nullptr;
    const diagnose::UnexplainedYaw target =
        diagnose::unexplained_yaw(diagnose::prepare_heading_track(log, nominal), nominal, d.yaw.values, shear);
    calibrate_disturbance(source, flown, water, identified, d, stem, options, target,
                          options.current_shear ? &shear_flown : nullptr);
  }
  r.yaw_disturbance_rad_s = flown.heading.yaw_disturbance_rad_s;
  r.yaw_disturbance_correlation_s = flown.heading.yaw_disturbance_correlation_s;
  const flightlog::FlightLog identified_log =
      fly(source, flown, water, identified, d.heading_noise_rad, stem + "_identified.csv", options);
  r.sil_identified = heading_metrics(identified_log, kSilSkipS);
  r.sil_speed = glide_speeds(identified_log, flown);
  fw::HeadingControlConfig compensated;
  compensated.law = fw::HeadingLaw::kCompensated;
  compensated.delay_s = r.loop_delay_s;  // told the identified dead time
  r.sil_compensated = heading_metrics(
      fly(source, flown, water, compensated, d.heading_noise_rad, stem + "_compensated.csv", options), kSilSkipS);
  return r;
}

}  // namespace glider::heading_study
