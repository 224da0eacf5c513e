// SPDX-License-Identifier: Apache-2.0
// glider-firmware: the flight software on the glider's Linux computer. Reads
// the target board file (devices) and the mission file (mission, limits,
// servo, safety), opens every device, then runs FlightSoftware through the
// Executive at absolute 1 s deadlines until the mission is complete or
// SIGTERM/SIGINT; logs, prints its statistics and exits cleanly.
// Under systemd (Type=notify, WatchdogSec=) it reports READY and feeds the
// watchdog after every healthy cycle (packaging/glider-firmware.service).
#include <CLI/CLI.hpp>
#include <array>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/firmware/executive.hpp"
#include "glider/firmware/flight_software.hpp"
#include "glider/target/linux_hal.hpp"
#include "glider/target/realtime_loop.hpp"
#include "glider/target/target_board.hpp"

namespace {

using namespace glider;

// The platform's part of each cycle, before the flight software: fresh
// blocking budgets on the Modbus buses. (The flight software reads every
// device itself, GPS and power included.)
class PlatformCycle final : public fw::PeriodicTask {
 public:
  explicit PlatformCycle(target::LinuxHal& hal) : hal_(hal) {}
  void run(hal::Micros) override { hal_.begin_cycle(); }

 private:
  target::LinuxHal& hal_;
};

// Start-up check: the flight software aborts on a sensor that has never
// given a value, so the sensors must speak before the first cycle. Polls
// until depth and attitude are valid; the message names what stayed silent.
std::string wait_for_sensors(const hal::Hal& hal, target::LinuxHal& linux_hal, double timeout_s) {
  const hal::Micros give_up = hal.clock.now_us() + static_cast<hal::Micros>(timeout_s * 1e6);
  bool depth = false;
  bool attitude = false;
  while (true) {
    linux_hal.begin_cycle();
    depth = depth || hal.depth.read().valid;
    attitude = attitude || hal.attitude.read().valid;
    if (depth && attitude) return "";
    if (hal.clock.now_us() > give_up) break;
    timespec pause{0, 100'000'000};
    nanosleep(&pause, nullptr);
  }
  std::string silent = depth ? "" : "depth transmitter";
  if (!attitude) silent += silent.empty() ? "compass" : " and compass";
  return "no valid reading from the " + silent + " within " + std::to_string(static_cast<int>(timeout_s)) +
         " s of start-up (see the counters below)";
}

std::string default_log_name(const std::filesystem::path& directory) {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "flight-%Y%m%dT%H%M%SZ.csv", std::gmtime(&now));
  return (directory / name).string();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Glider flight software on the Linux target"};
  std::string board_path = "/etc/glider/target/board.toml";
  std::string mission_path = "/etc/glider/missions/mission.toml";
  std::string log_path;
  std::string actuators_tcp;
  std::uint64_t max_cycles = 0;
  bool no_realtime = false;
  double sensor_wait_s = 30.0;
  app.add_option("--board", board_path, "target board file (devices, loop)")->capture_default_str();
  app.add_option("--mission", mission_path, "mission file (mission, limits, servo, safety)")->capture_default_str();
  app.add_option("--log", log_path, "flight log file (default: a new file in the board's log directory)");
  app.add_option("--actuators-tcp", actuators_tcp, "override the actuator bus with Modbus TCP HOST:PORT (bench)");
  app.add_option("--max-cycles", max_cycles, "stop after this many cycles (0: until done or SIGTERM)");
  app.add_option("--sensor-wait-s", sensor_wait_s, "start-up: wait this long for depth and attitude")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("--no-realtime", no_realtime, "do not ask for SCHED_FIFO or mlockall whatever the board says");
  CLI11_PARSE(app, argc, argv);
  target::block_stop_signals();  // before the log's writer thread exists

  std::FILE* out = stderr;  // journald takes stderr under systemd
  target::TargetBoard board;
  fw::FlightSoftwareConfig config;
  std::unique_ptr<target::LinuxHal> linux_hal;
  try {
    board = target::load_target_board(board_path);
    const auto mission = config::TomlDocument::load(mission_path);
    config = fw::read_flight_config(mission);  // validated there
    mission.reject_unknown_keys();
    target::LinuxHalOptions options;
    options.actuators_tcp = actuators_tcp;
    if (log_path.empty()) {
      std::filesystem::create_directories(board.log_directory);
      log_path = default_log_name(board.log_directory);
    }
    options.log_path = log_path;
    linux_hal = target::LinuxHal::build(board, options, out);
  } catch (const std::exception& error) {
    std::fprintf(out, "glider-firmware: %s\n", error.what());
    return 1;
  }
  if (no_realtime) board.loop.sched_fifo = board.loop.lock_memory = false;
  const std::string warning = target::apply_realtime(board.loop);
  if (!warning.empty()) std::fprintf(out, "glider-firmware: warning: %s\n", warning.c_str());

  const hal::Hal hal = linux_hal->hal();
  if (const std::string silent = wait_for_sensors(hal, *linux_hal, sensor_wait_s); !silent.empty()) {
    std::fprintf(out, "glider-firmware: %s\n", silent.c_str());
    linux_hal->log().close();
    linux_hal->print_statistics(out);
    return 1;
  }
  fw::FlightSoftware flight(hal, config);
  PlatformCycle platform(*linux_hal);
  const std::array<fw::TaskSlot, 2> tasks{{{"platform", &platform, 1, 450'000}, {"flight", &flight, 1, 500'000}}};
  fw::Executive executive(hal.clock, tasks);
  flight.attach_executive(&executive);
  if (!executive.valid()) {
    std::fprintf(out, "glider-firmware: invalid task table\n");
    return 1;
  }
  std::fprintf(out, "glider-firmware: board %s, mission %s, flight log %s; flying\n", board.name.c_str(),
               mission_path.c_str(), log_path.c_str());
  std::fflush(out);

  target::StopReason reason = target::StopReason::kError;
  try {
    target::RealtimeLoop loop(executive, board.loop, out);
    std::uint32_t overruns_seen = 0;
    reason = loop.run([&] { return flight.complete(); },
                      [&] {
                        const bool healthy = executive.stats().overruns == overruns_seen;
                        overruns_seen = executive.stats().overruns;
                        return healthy;
                      },
                      max_cycles);
    char line[256];
    loop.timing().format(line, sizeof line);
    std::fprintf(out, "glider-firmware: loop: %s; watchdog %s (%llu pings)\n", line,
                 loop.watchdog_enabled() ? "on" : "off", static_cast<unsigned long long>(loop.watchdog_pings()));
  } catch (const std::exception& error) {
    std::fprintf(out, "glider-firmware: %s\n", error.what());
  }
  const char* why = reason == target::StopReason::kSignal ? "stopped by signal"
                    : reason == target::StopReason::kDone ? "done"
                                                          : "loop error";
  std::fprintf(out, "glider-firmware: %s; phase %s, %d yos, abort cause %s, %llu log rows lost\n", why,
               fw::to_string(flight.phase()), flight.yos_completed(), fw::to_string(flight.abort_cause()),
               static_cast<unsigned long long>(flight.log_rows_lost()));
  const bool log_ok = linux_hal->log().close();
  linux_hal->print_statistics(out);
  if (!log_ok) std::fprintf(out, "glider-firmware: %s: writing the flight log failed\n", log_path.c_str());
  return reason == target::StopReason::kError || !log_ok ? 1 : 0;
}
