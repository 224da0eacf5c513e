// SPDX-License-Identifier: Apache-2.0
#pragma once
// The plant: the vehicle model (the SIL's simulator and sensor models)
// behind the glider's real interfaces, advanced in lockstep with the wall
// clock at a time scale. One thread: poll() on every device, the model
// stepped at its integration step (0.1 s simulated) at absolute wall-clock
// deadlines, so the plant never drifts from the firmware's scaled clock.
//
// The model is held at its launch state (floating at rest, on deck) until
// the firmware's first actuator command; simulated time and the fault
// times count from there, as in glider-sil, whose t = 0 is the firmware's
// first cycle.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "glider/model/environment.hpp"
#include "glider/model/vehicle.hpp"
#include "modbus_tcp_server.hpp"
#include "plant_faults.hpp"

namespace glider::plant {

struct PlantOptions {
  model::VehicleParams vehicle;
  model::Environment environment;
  std::filesystem::path actuator_board;     // the register map served
  std::filesystem::path directory;          // ptys, board files, logs
  std::string truth_path;                   // CSV of the model's truth at 1 s (optional)
  std::uint64_t seed = 1;                   // sensor noise and GPS, as glider-sil --seed
  double heading_deg = 90.0;                // as glider-sil --heading-deg
  double max_working_depth_m = 100.0;       // the board's [vehicle], as glider-sil --max-working-depth-m
  std::string heading_law = "compensated";  // as glider-sil --heading-law
  double time_scale = 1.0;                  // simulated seconds per wall second
  double duration_s = 0.0;                  // stop this long after launch (0: at SIGTERM/SIGINT)
  double compass_interval_s = 0.5;          // $PTNTHPR cadence (simulated)
  TcpServerOptions tcp;
  // The Iridium modem on a pty (board [modem]) bridged to this shore
  // station over TCP; port 0: no modem (the vehicle never calls).
  std::string shore_host = "127.0.0.1";
  int shore_port = 0;
  std::string vehicle_name;  // the dialog's name (board modem.vehicle_name); empty: the vehicle's
  std::vector<PlantFault> faults;
};

// Runs until SIGTERM/SIGINT or the duration; prints its endpoints (one
// "glider-plant: ready" line, flushed) and at the end its statistics to
// `out`. Throws std::runtime_error (or config::ConfigError) on a setup error.
void run_plant(const PlantOptions& options, std::FILE* out);

}  // namespace glider::plant
