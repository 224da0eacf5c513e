// SPDX-License-Identifier: Apache-2.0
// glider-plant: hardware in the loop on a laptop. Serves the glider's real
// interfaces (Modbus TCP actuator axes, the Keller depth transmitter over
// Modbus RTU, GPS and compass NMEA, on pseudo-terminals) from the vehicle
// model at a time scale, and writes the target board file glider-firmware
// flies with (docs/hil.md).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/model/environment_file.hpp"
#include "glider/model/vehicle_file.hpp"
#include "plant.hpp"

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-plant", "Hardware in the loop: the vehicle model behind the glider's real interfaces");
  CLI::App& app = tool.app();
  std::string vehicle_path;
  std::string env_path;
  std::string actuators_path = glider::cli::boards_dir() + "/actuators/three_axis_modbus.toml";
  std::string directory;
  std::vector<std::string> fault_texts;
  bool list_faults = false;
  glider::plant::PlantOptions options;
  tool.add_vehicle_option(vehicle_path);
  app.add_option("--env", env_path, "environment file: water profile, currents (TOML)")->check(CLI::ExistingFile);
  app.add_option("--actuators", actuators_path, "actuator board served over Modbus TCP (register map, axes)")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  app.add_option("--dir", directory, "directory for the devices (gps, compass, depth), board.toml and logs/");
  tool.add_integer("--seed", options.seed, 0, glider::cli::kMaxSeed, "",
                   "seed of the sensor noise and GPS (as glider-sil --seed)")
      ->capture_default_str();
  tool.add_number("--heading-deg", options.heading_deg, {-360.0, 360.0, "deg"},
                  "initial heading (as glider-sil --heading-deg)")
      ->capture_default_str();
  tool.add_number("--max-working-depth-m", options.max_working_depth_m, {1.0, 11000.0, "m"},
                  "board [vehicle] depth rating (as glider-sil --max-working-depth-m)")
      ->capture_default_str();
  app.add_option("--heading-law", options.heading_law, "board [vehicle] fin autopilot (as glider-sil --heading-law)")
      ->capture_default_str()
      ->check(CLI::IsMember({"proportional", "slocum", "compensated"}));
  tool.add_number("--time-scale", options.time_scale, {0.01, 1000.0, ""},
                  "simulated seconds per wall second (glider-firmware's the same)")
      ->capture_default_str();
  tool.add_number("--duration-s", options.duration_s, {0.0, 1e9, "s"},
                  "stop this long (simulated) after launch; 0: at SIGTERM")
      ->capture_default_str();
  tool.add_number("--compass-interval-s", options.compass_interval_s, {0.1, 10.0, "s"},
                  "$PTNTHPR cadence, simulated: a whole number of model steps (0.1 s); a Slocum reads its "
                  "attitude every cycle (c_att_time 0)")
      ->capture_default_str();
  std::string shore;
  app.add_option("--shore", shore,
                 "serve the Iridium modem on a pty (board [modem]) and bridge its calls to this shore station: "
                 "HOST:PORT over TCP (numeric host; docs/comms.md)");
  app.add_option("--vehicle-name", options.vehicle_name, "the name the vehicle gives in its dialog (with --shore)");
  app.add_option("--fault", fault_texts, "plant fault NAME@TIME after launch (s, m or h), repeatable; --list-faults");
  app.add_flag("--list-faults", list_faults, "print the plant faults and their glider-sil counterparts");
  app.add_option("--truth", options.truth_path, "write the model's truth at 1 s to this CSV");
  app.add_option("--host", options.tcp.host, "Modbus TCP address to serve on (numeric)")->capture_default_str();
  tool.add_integer("--port", options.tcp.port, 0, 65535, "", "Modbus TCP port (0: any free one, printed)")
      ->capture_default_str();
  tool.add_integer("--max-clients", options.tcp.max_clients, 1, 4096, "", "Modbus TCP connection cap")
      ->capture_default_str();
  tool.add_integer("--request-timeout-ms", options.tcp.request_timeout_ms, 1, 600'000, "ms",
                   "a client's unfinished request is dropped after")
      ->capture_default_str();
  tool.add_integer("--idle-timeout-ms", options.tcp.idle_timeout_ms, 1, 86'400'000, "ms",
                   "a silent client is dropped after")
      ->capture_default_str();
  return tool.run(argc, argv, [&] {
    if (list_faults) {
      for (const auto& f : glider::plant::plant_fault_names()) {
        std::printf("%-15s %s (glider-sil: %s)\n", f.name.c_str(), f.what.c_str(), f.sil.c_str());
      }
      return glider::cli::kOk;
    }
    if (directory.empty()) throw glider::cli::ToolError(glider::cli::kUsage, "--dir is required");
    for (const std::string& text : fault_texts) {
      std::string error;
      const auto fault = glider::plant::parse_plant_fault(text, error);
      if (!fault) throw glider::cli::ToolError(glider::cli::kUsage, "--fault " + error);
      options.faults.push_back(*fault);
    }
    if (!shore.empty()) {
      const std::size_t colon = shore.rfind(':');
      char* end = nullptr;
      const long port = colon == std::string::npos ? 0 : std::strtol(shore.c_str() + colon + 1, &end, 10);
      if (colon == std::string::npos || end == nullptr || *end != '\0' || port < 1 || port > 65535) {
        throw glider::cli::ToolError(glider::cli::kUsage, "--shore " + shore + ": expected HOST:PORT, port 1-65535");
      }
      options.shore_host = shore.substr(0, colon);
      options.shore_port = static_cast<int>(port);
    }
    options.vehicle = glider::model::load_vehicle_file(vehicle_path);
    options.environment = env_path.empty() ? glider::model::still_water(options.vehicle.trim_density_kg_m3)
                                           : glider::model::load_environment_file(env_path);
    options.actuator_board = actuators_path;
    options.directory = directory;
    glider::plant::run_plant(options, stdout);
    return glider::cli::kOk;
  });
}
