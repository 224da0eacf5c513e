// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/scenario.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

#include "glider/firmware/app/absent_devices.hpp"
#include "glider/firmware/app/flight_application.hpp"
#include "glider/firmware/comms/file_access_posix.hpp"
#include "glider/firmware/comms/log_forward.hpp"
#include "glider/firmware/comms/zmodem_transfer.hpp"
#include "glider/firmware/log/slocum_directory_sink.hpp"
#include "glider/firmware/log/slocum_lz4_sink.hpp"
#include "glider/model/simulator.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/portable_random.hpp"
#include "glider/units.hpp"

namespace glider::sil {
namespace {

// The firmware must not be configured to drive the servos past the vehicle's
// real travel: refuse such a pairing before launch.
std::string check_limits(const model::VehicleParams& v, const fw::ActuatorLimits& l) {
  const double tolerance = 1e-9;
  if (cc_to_m3(l.ballast_min_cc) < v.ballast.volume_min_m3 - tolerance ||
      cc_to_m3(l.ballast_max_cc) > v.ballast.volume_max_m3 + tolerance) {
    return "firmware ballast limits exceed the vehicle's buoyancy engine";
  }
  if (in_to_m(l.battery_min_in) < v.battery.travel_min_m - tolerance ||
      in_to_m(l.battery_max_in) > v.battery.travel_max_m + tolerance) {
    return "firmware battery limits exceed the vehicle's slide travel";
  }
  return "";
}

// The vehicle's random yaw (heading.yaw_disturbance_*): first-order
// Gauss-Markov, exact over each cycle, held through it.
class YawDisturbance {
 public:
  YawDisturbance(const model::HeadingModel& heading, std::uint64_t seed)
      : rms_(heading.yaw_disturbance_rad_s), tau_(heading.yaw_disturbance_correlation_s), random_(seed) {}
  double next(double dt_s) {
    if (!(rms_ > 0.0)) return 0.0;
    const double a = std::exp(-dt_s / tau_);
    value_ = a * value_ + rms_ * std::sqrt(1.0 - a * a) * random_.gaussian();
    return value_;
  }

 private:
  double rms_, tau_;
  PortableRandom random_;
  double value_ = 0.0;
};

class NullLogSink final : public hal::LogSink {
 public:
  bool write(const hal::FlightLogRecord&) override { return true; }
};

}  // namespace

ScenarioResult run_scenario(const model::VehicleParams& vehicle, const fw::FlightSoftwareConfig& config,
                            const ScenarioOptions& options) {
  ScenarioResult result;
  result.error = check_limits(vehicle, config.limits);
  if (result.error.empty()) {
    const char* problem = fw::validate(config);
    if (problem[0] != '\0') result.error = std::string("mission refused: ") + problem;
  }
  if (!result.error.empty()) return result;

  model::GliderSimulator sim(vehicle, options.environment, options.integration_step_s);
  sim.reset_at_surface(cc_to_m3(config.limits.ballast_max_cc), 0.0, deg_to_rad(options.heading_deg));
  SimClock clock;
  SimHal sim_hal(sim, clock, options.noise, options.seed, options.peripherals);
  std::vector<bool> fault_applied(options.faults.size(), false);

  Metadata metadata = options.metadata;
  metadata.emplace_back("seed", std::to_string(options.seed));
  // The SIL flew the file's Reynolds exponent (0 where the file is silent):
  // its logs state it, so a diagnosis of them flies the SIL's own drag, not
  // the prior for a real glider (diagnose.hpp: drag_reynolds_exponent_for).
  model::VehicleParams logged = options.logged_vehicle.value_or(vehicle);
  logged.hydro.cd0_reynolds_exponent_stated = true;
  for (auto& entry : model::vehicle_metadata(logged)) {
    metadata.push_back(std::move(entry));
  }

  NullLogSink no_file;
  std::optional<CsvFlightLog> csv;
  if (!options.log_path.empty()) {
    const bool binary = options.log_path.ends_with(kBinaryLogSuffix);
    csv.emplace(options.log_path, metadata, sim, SimCtd(options.noise, derived_seed(options.seed, kCtdStream)),
                options.log_gaps, derived_seed(options.seed, kLogGapStream),
                binary ? LogEncoding::kBinary : LogEncoding::kCsv);
    if (!csv->ok()) {
      result.error = csv->error();
      return result;
    }
  }
  hal::LogSink& file_sink = csv ? static_cast<hal::LogSink&>(*csv) : no_file;
  // The Slocum files: set up (sink, caches) before the first cycle.
  std::optional<fw::SlocumDirectorySink> slocum_sink;
  std::optional<fw::SlocumLz4Sink> slocum_lz4;
  std::optional<fw::SlocumLogger> slocum;
  std::optional<fw::SlocumLogSink> slocum_rows;
  if (!options.slocum_directory.empty()) {
    slocum_sink.emplace(options.slocum_directory);
    if (!slocum_sink->ok()) {
      result.error = slocum_sink->error();
      return result;
    }
    if (options.slocum_lz4) slocum_lz4.emplace(*slocum_sink);
    slocum.emplace(slocum_lz4 ? static_cast<fw::SlocumSink&>(*slocum_lz4) : *slocum_sink, options.slocum);
    if (!slocum->start()) {
      result.error = options.slocum_directory + ": " + slocum->error();
      return result;
    }
    slocum_rows.emplace(*slocum);
  }
  TeeLogSink file_and_stats(file_sink, result.stats);
  TeeLogSink log(file_and_stats, slocum_rows ? static_cast<hal::LogSink&>(*slocum_rows) : no_file);
  fw::comms::LogForward log_path(log);  // through the comms task's tap once it exists

  // What the vehicle is not fitted with, the firmware gets as absent devices.
  const fw::app::FittedDevices& fitted = options.fitted;
  fw::app::FixedRudder fixed_rudder(clock);
  fw::app::NoDigitalInput no_leak;
  fw::app::NoDigitalOutput no_drop_weight;
  fw::app::NoPowerMonitor no_power;
  const hal::Hal hal{
      .clock = clock,
      .depth = sim_hal.depth(),
      .attitude = sim_hal.attitude(),
      .pump = sim_hal,
      .battery = sim_hal,
      .log = log_path,
      .rudder = fitted.rudder ? sim_hal.rudder() : static_cast<hal::Rudder&>(fixed_rudder),
      .gps = sim_hal.gps(),
      .leak = fitted.leak_detector ? static_cast<hal::DigitalInput&>(sim_hal.leak()) : no_leak,
      .drop_weight = fitted.drop_weight ? static_cast<hal::DigitalOutput&>(sim_hal.drop_weight()) : no_drop_weight,
      .power = fitted.power_monitor ? static_cast<hal::PowerMonitor&>(sim_hal.power()) : no_power};
  fw::app::FlightApplication app(hal, config, nullptr, options.period_us);
  fw::Executive& executive = app.executive();
  const fw::FlightSoftware& flight = app.flight();

  // The segments still open are not offered to a send.
  struct OpenSegments final : fw::comms::OpenFiles {
    const fw::SlocumDirectorySink* sink = nullptr;
    bool is_open(const char* name) const override { return sink != nullptr && sink->is_open(name); }
  } open_segments;
  std::optional<SimModem> modem;
  std::optional<fw::comms::CommsTask> comms;
  // With Slocum files and no engine given: Zmodem from the Slocum folder,
  // uploads into its from-shore/ folder.
  std::optional<fw::comms::PosixFileAccess> outgoing_files, incoming_files;
  std::optional<fw::comms::ZmodemTransfer> zmodem;
  if (options.comms && options.comms->transfer == nullptr && slocum_sink) {
    const std::string incoming = options.slocum_directory + "/from-shore";
    std::error_code ec;
    std::filesystem::create_directories(incoming, ec);
    if (ec) {
      result.error = incoming + ": cannot create: " + ec.message();
      return result;
    }
    open_segments.sink = &*slocum_sink;
    outgoing_files.emplace(options.slocum_directory);
    incoming_files.emplace(incoming);
    zmodem.emplace(options.slocum_directory.c_str(), *outgoing_files, incoming.c_str(), *incoming_files,
                   &open_segments);
  }
  if (options.comms) {
    const ScenarioOptions::Comms& c = *options.comms;
    fw::comms::CommsConfig comms_config = c.config;
    comms_config.gps_wait_s = config.plan.gps_wait_s;
    comms_config.keystroke_wait_s = config.plan.surface_dwell_s;
    comms_config.printout_cycle_s = config.plan.printout_cycle_s;
    comms_config.utc_at_zero_s = c.utc_at_launch_s;
    modem.emplace(clock, c.link, c.far_end, derived_seed(options.seed, kModemStream));
    comms.emplace(app.flight(), *modem, sim_hal.gps(), log, comms_config,
                  c.transfer != nullptr ? c.transfer : (zmodem ? &*zmodem : nullptr), c.reloader);
    comms->set_log_progress(c.log_progress);
    log_path.retarget(*comms);
    app.attach_comms(*comms);
  }
  double call_cycle_sum_us = 0.0;
  if (options.before_launch) options.before_launch(app.flight());

  const double period_s = hal::to_seconds(options.period_us);
  YawDisturbance yaw_disturbance(vehicle.heading, derived_seed(options.seed, kYawDisturbanceStream));
  while (sim.time_s() <= options.max_sim_time_s) {
    if (options.before_cycle) options.before_cycle(sim.time_s(), sim_hal);
    for (std::size_t i = 0; i < options.faults.size(); ++i) {
      if (!fault_applied[i] && sim.time_s() >= options.faults[i].at_s) {
        fault_applied[i] = true;
        sim_hal.inject(options.faults[i].name);
      }
    }
    const bool in_call = comms && modem->in_call();
    const auto cycle_start = std::chrono::steady_clock::now();
    executive.step();
    if (in_call) {
      const double us =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - cycle_start).count();
      ++result.call_cycles;
      call_cycle_sum_us += us;
      result.call_cycle_max_us = std::max(result.call_cycle_max_us, us);
    }
    // A shore answering in wall time is given its time to answer here,
    // between two cycles, while the glider listens (TcpShore).
    if (comms) modem->end_of_cycle(comms->state() == fw::comms::CommsState::kDialog);
    if (comms && options.comms->after_cycle) options.comms->after_cycle(sim.time_s(), *comms);
    if (comms && comms->reset_requested() && comms->state() == fw::comms::CommsState::kDone) {
      result.reset_requested = true;
      break;
    }
    const bool calling = comms && !comms->idle() && comms->state() != fw::comms::CommsState::kDone;
    const model::Truth truth = sim.truth();
    if (options.stop_when && options.stop_when(sim.time_s(), flight, truth)) break;
    if (flight.navigator().waypoints_reached() > static_cast<std::int32_t>(result.waypoints.size())) {
      result.waypoints.push_back({flight.navigator().waypoints_reached(), sim.time_s(), truth.east_m, truth.north_m});
    }
    if (flight.phase() == fw::Phase::kAbort) {
      if (result.abort_time_s < 0.0) result.abort_time_s = sim.time_s();
      if (result.abort_surfaced_s < 0.0 && truth.depth_m < options.peripherals.gps.antenna_out_depth_m) {
        result.abort_surfaced_s = sim.time_s();
      }
      if (sim.time_s() - result.abort_time_s >= options.stop_after_abort_s) break;
    }
    // An aborted mission is complete for the firmware once its depth says
    // it is up; the run goes on until the antenna is truly out (or the stop).
    if (flight.complete() && !calling && !(result.abort_time_s >= 0.0 && result.abort_surfaced_s < 0.0)) break;
    sim.set_yaw_disturbance_rad_s(yaw_disturbance.next(period_s));
    sim.advance(period_s);
    clock.advance(options.period_us);
  }

  if (comms) {
    result.comms = comms->stats();
    result.modem = modem->stats();
    if (result.call_cycles > 0) result.call_cycle_mean_us = call_cycle_sum_us / static_cast<double>(result.call_cycles);
  }
  result.completed = flight.complete();
  result.final_phase = flight.phase();
  result.abort_cause = flight.abort_cause();
  result.yos = flight.yos_completed();
  result.sim_time_s = sim.time_s();
  result.final_truth = sim.truth();
  result.executive = executive.stats();
  result.drop_weight_released = sim_hal.drop_weight().released();
  result.energy_used_j = sim_hal.power().energy_used_j();
  result.charge_used_amphr = sim_hal.power().read().charge_used_amphr;
  result.log_rows_lost = flight.log_rows_lost();
  if (csv) {
    result.log_rows = csv->rows();
    const std::string outcome = result.final_phase == fw::Phase::kAbort
                                    ? std::string("aborted ") + fw::cause_id(result.abort_cause)
                                : result.completed ? std::string("complete")
                                                   : std::string("stopped max_sim_time");
    if (!csv->finish(outcome, result.log_rows_lost)) result.error = csv->error();
  }
  if (slocum) {
    const bool slocum_ok = slocum->finish();
    result.slocum_segments = slocum->segments();
    result.slocum_dbd = slocum->dbd();
    result.slocum_sbd = slocum->sbd();
    result.slocum_unrepresentable = slocum->unrepresentable();
    if (!slocum_ok && result.error.empty()) {
      result.error = options.slocum_directory + ": " + std::to_string(slocum->dbd().cycles_lost) + " .dbd and " +
                     std::to_string(slocum->sbd().cycles_lost) + " .sbd cycles could not be written";
    }
  }
  if (result.error.empty() && result.log_rows_lost > 0) {
    result.error = std::to_string(result.log_rows_lost) + " log rows could not be written";
  }
  return result;
}

}  // namespace glider::sil
