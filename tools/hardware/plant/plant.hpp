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
  // $PTNTHPR cadence (simulated): every model step by default. A Slocum
  // samples its attitude every control cycle (c_att_time 0 in every row of
  // every .dbd in tests/data/real/dbd: m_pitch, m_roll and m_heading are
  // logged each cycle), so a reading is as fresh as the cycle; the plant's
  // freshest is its step. At 0.5 s the firmware's pitch lagged the plant's
  // by 0.18 s more through the inflections (median of 8 waypoint flights
  // each, tests/hil/inflection_dr.py), by 0 to 0.5 s in a flight depending
  // on where the plant's launch put its 0.5 s grid.
  double compass_interval_s = 0.1;
  // The lateness record (lateness_record.hpp): DIR/lateness.csv, rows from
  // this many wall milliseconds late.
  double record_late_ms = 20.0;
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
