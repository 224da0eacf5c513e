// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glider/firmware/app/vehicle_setup.hpp"
#include "glider/firmware/comms/comms_task.hpp"
#include "glider/firmware/executive.hpp"
#include "glider/firmware/flight_software.hpp"
#include "glider/firmware/log/slocum_writer.hpp"
#include "glider/model/environment.hpp"
#include "glider/model/simulator.hpp"
#include "glider/model/vehicle.hpp"
#include "glider/sil/csv_flight_log.hpp"
#include "glider/sil/fault_injection.hpp"
#include "glider/sil/flight_stats.hpp"
#include "glider/sil/sim_hal.hpp"
#include "glider/sil/sim_modem.hpp"

namespace glider::sil {

// A log path ending in this is written in the log's binary form
// (LogEncoding::kBinary), any other as CSV.
inline constexpr std::string_view kBinaryLogSuffix = ".glb";

struct ScenarioOptions {
  std::uint64_t seed = 1;
  double heading_deg = 90.0;
  SensorNoise noise{};
  model::Environment environment{};
  double max_sim_time_s = 6.0 * 3600.0;  // the runner's own stop, beyond the mission's
  hal::Micros period_us = fw::Executive::kDefaultPeriodUs;
  // The plant's integration step (model::GliderSimulator; docs/sil.md, Speed).
  double integration_step_s = model::GliderSimulator::kDefaultStepS;
  std::string log_path;  // empty: no log; ending in kBinaryLogSuffix: the binary form
  Metadata metadata;     // extra `# key: value` lines (vehicle.* are added)
  LogGaps log_gaps;      // thin the CSV like a real Slocum log (off by default)
  // The vehicle the log's vehicle.* metadata states; default: the one flown.
  // Tests that hide an effect fly a modified vehicle and log the nominal one.
  std::optional<model::VehicleParams> logged_vehicle;
  // Called before every firmware cycle with the simulated time: tests inject
  // faults through it.
  std::function<void(double sim_time_s, SimHal& hal)> before_cycle;
  // Faults switched on at a simulated time (`--fault NAME@T`).
  std::vector<ScheduledFault> faults;
  PeripheralModels peripherals{};  // GPS (launch position) and energy model
  // The devices the vehicle carries (its vehicle file's [fitted]); one that is
  // not fitted is an absent stand-in in the HAL, as on a target board without it.
  // Default: everything the SimHal simulates.
  fw::app::FittedDevices fitted{.drop_weight = true, .leak_detector = true, .rudder = true, .power_monitor = true};
  // An aborted firmware stays in its abort state for good; the run stops
  // this long after the abort (the vehicle is up by then, or never will be).
  double stop_after_abort_s = 3600.0;
  // The firmware's Slocum data files (.dbd/.sbd, cac/; docs/slocum-binary.md,
  // "Writing") into this directory; empty: none.
  std::string slocum_directory;
  bool slocum_lz4 = false;  // their LZ4 forms instead (.dcd/.scd, cac/*.ccc)
  fw::SlocumLogOptions slocum;
  // Comms (docs/comms.md): the simulated modem and link, the far end it
  // calls, and the vehicle's comms settings (the surface waits come from the
  // mission plan). None: the vehicle never calls.
  struct Comms {
    fw::comms::CommsConfig config;
    LinkModel link;
    FarEnd* far_end = nullptr;
    fw::comms::FileTransfer* transfer = nullptr;
    fw::comms::MissionReloader* reloader = nullptr;
    // A log written after the cycle (as the target's writer thread): null, as
    // SIL writes within the cycle. Tests model a slow writer with it.
    fw::comms::LogProgress* log_progress = nullptr;
    double utc_at_launch_s = 1.7e9;  // Curr Time at launch
    // Called after every cycle (tests sample the comms state).
    std::function<void(double sim_time_s, const fw::comms::CommsTask& comms)> after_cycle;
  };
  std::optional<Comms> comms;
  // Called once before the first cycle (a forecast seeds the navigator's
  // current estimate through it).
  std::function<void(fw::FlightSoftware& flight)> before_launch;
  // Checked after every cycle: true ends the run there (a forecast stops at
  // the next surfacing).
  std::function<bool(double sim_time_s, const fw::FlightSoftware& flight, const model::Truth& truth)> stop_when;
};

// Where the vehicle truly was when the firmware counted a waypoint reached.
struct WaypointEvent {
  std::int32_t reached = 0;  // count after this one
  double time_s = 0.0;
  double east_m = 0.0;  // truth, from the launch point
  double north_m = 0.0;
};

struct ScenarioResult {
  bool completed = false;  // the firmware declared the mission over
  fw::Phase final_phase = fw::Phase::kSurface;
  fw::AbortCause abort_cause = fw::AbortCause::kNone;
  std::int32_t yos = 0;
  double sim_time_s = 0.0;
  model::Truth final_truth;  // where the vehicle really is at the end
  FlightStats stats;
  fw::ExecutiveStats executive;
  std::uint64_t log_rows = 0;
  std::uint64_t log_rows_lost = 0;
  bool drop_weight_released = false;
  std::vector<WaypointEvent> waypoints;
  double abort_time_s = -1.0;      // first cycle in the abort phase
  double abort_surfaced_s = -1.0;  // first time after it that the antenna was truly out of the water
  double energy_used_j = 0.0;
  // The Slocum files (when slocum_directory was given).
  std::int32_t slocum_segments = 0;
  fw::SlocumFileCounters slocum_dbd;
  fw::SlocumFileCounters slocum_sbd;
  std::uint64_t slocum_unrepresentable = 0;  // values the sensors' types cannot hold (not stored)
  double charge_used_amphr = 0.0;
  std::string error;  // set when the run could not start or the log failed
  // With comms: the task's and the modem's counts, and the wall time of the
  // control cycles spent in a call (the loop's cost during the dialog).
  fw::comms::CommsStats comms;
  SimModemStats modem;
  std::uint64_t call_cycles = 0;
  double call_cycle_mean_us = 0.0;
  double call_cycle_max_us = 0.0;
  bool reset_requested = false;
};

// Flies the flight software against the model in lockstep: one firmware
// cycle, then the plant advances one period. Deterministic for a given
// vehicle, configuration and options.
ScenarioResult run_scenario(const model::VehicleParams& vehicle, const fw::FlightSoftwareConfig& config,
                            const ScenarioOptions& options);

}  // namespace glider::sil
