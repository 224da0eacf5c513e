// SPDX-License-Identifier: Apache-2.0
// glider-firmware: the flight software on the glider's Linux computer. Reads
// the target board file (devices, the vehicle's limits and fitted devices)
// and the mission (a Slocum .mi with its .ma files, or TOML) through the
// flight application shared with glider-sil (glider/firmware/app/), opens
// every device, then runs the application's executive at absolute deadlines
// on the loop clock until the mission is complete or SIGTERM/SIGINT; logs,
// prints its statistics and exits.
// Under systemd (Type=notify, WatchdogSec=) it reports READY and feeds the
// watchdog after every healthy cycle (packaging/glider-firmware.service).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/firmware/app/flight_application.hpp"
#include "glider/firmware/app/mission_reload.hpp"
#include "glider/firmware/app/mission_setup.hpp"
#include "glider/firmware/app/reload_arena.hpp"
#include "glider/firmware/comms/comms_task.hpp"
#include "glider/firmware/comms/file_access_posix.hpp"
#include "glider/firmware/comms/log_forward.hpp"
#include "glider/firmware/comms/zmodem_transfer.hpp"
#include "glider/firmware/log/slocum_directory_sink.hpp"
#include "glider/firmware/log/slocum_list.hpp"
#include "glider/firmware/log/slocum_lz4_sink.hpp"
#include "glider/firmware/log/slocum_writer.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "glider/hal_linux/serial_modem.hpp"
#include "glider/target/linux_hal.hpp"
#include "glider/target/realtime_loop.hpp"
#include "glider/target/target_board.hpp"
#include "glider/utc_time.hpp"

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

hal::Micros utc_now_us() {
  timespec t{};
  clock_gettime(CLOCK_REALTIME, &t);
  return static_cast<hal::Micros>(t.tv_sec) * hal::kMicrosPerSecond + t.tv_nsec / 1000;
}

// `exit reset` typed at the console: the service restarts the firmware.
constexpr int kExitReset = 4;

// What the comms task needs from the board's [modem] and the mission's surface behaviour.
fw::comms::CommsConfig comms_config(const target::ModemBoardConfig& modem, const fw::FlightSoftwareConfig& flight,
                                    const std::string& mission_path, hal::Micros clock_now_us) {
  fw::comms::CommsConfig c;
  std::snprintf(c.vehicle_name, sizeof c.vehicle_name, "%s", modem.vehicle_name.c_str());
  std::snprintf(c.primary_number, sizeof c.primary_number, "%s", modem.primary_number.c_str());
  std::snprintf(c.secondary_number, sizeof c.secondary_number, "%s", modem.secondary_number.c_str());
  std::snprintf(c.mission_name, sizeof c.mission_name, "%s",
                std::filesystem::path(mission_path).filename().string().c_str());
  for (const std::string& name : modem.dialog_sensors) {
    if (c.sensor_count == c.sensors.size()) break;
    std::snprintf(c.sensors[c.sensor_count++].data(), fw::comms::kTextField, "%s", name.c_str());
  }
  c.gps_wait_s = flight.plan.gps_wait_s;
  c.keystroke_wait_s = flight.plan.surface_dwell_s;
  c.printout_cycle_s = flight.plan.printout_cycle_s;
  if (modem.reply_window_s) c.reply_window_s = *modem.reply_window_s;
  const double utc_now_s = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  c.utc_at_zero_s = utc_now_s - hal::to_seconds(clock_now_us);
  return c;
}

// The wake-up lateness of the cycles that ran while a Zmodem transfer did
// (after the loop: this sorts a copy), exact: the HIL check of a call's cost
// reads it (tests/comms_e2e/check_hil_e2e.py).
void print_transfer_lateness(std::span<const hal::Micros> late_us, std::FILE* out) {
  if (late_us.empty()) return;
  std::vector<hal::Micros> sorted(late_us.begin(), late_us.end());
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&sorted](double q) {
    return static_cast<long long>(sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))]);
  };
  std::fprintf(out,
               "glider-firmware: loop during transfers: cycles %zu, wake-up late median %lld us, p99 %lld us, "
               "max %lld us\n",
               sorted.size(), at(0.5), at(0.99), static_cast<long long>(sorted.back()));
}

std::string default_log_name(const std::filesystem::path& directory) {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return (directory / ("flight-" + glider::utc::format_compact(std::chrono::duration<double>(now).count()) + "Z.csv"))
      .string();
}

}  // namespace

int main(int argc, char** argv) {
  cli::Tool tool("glider-firmware", "Glider flight software on the Linux target");
  CLI::App& app = tool.app();
  std::string board_path = "/etc/glider/target/board.toml";
  std::string mission_path = "/etc/glider/missions/mission.mi";
  std::string log_path;
  std::string actuators_tcp;
  std::uint64_t max_cycles = 0;
  bool no_realtime = false;
  bool check_mission = false;
  double sensor_wait_s = 30.0;
  double time_scale = 1.0;
  std::int32_t legs = 0;
  app.add_option("--board", board_path, "target board file (devices, vehicle limits, loop)")->capture_default_str();
  app.add_option("--mission", mission_path, "mission: Slocum .mi (its .ma files in ../mafiles) or TOML")
      ->capture_default_str();
  app.add_option("--log", log_path, "flight log file (default: a new file in the board's log directory)");
  app.add_option("--actuators-tcp", actuators_tcp, "override the actuator bus with Modbus TCP HOST:PORT (bench)")
      ->check(
          CLI::Validator([](std::string& text) { return glider::hal_linux::tcp_endpoint_problem(text); }, "HOST:PORT"));
  tool.add_integer("--max-cycles", max_cycles, 0, std::numeric_limits<std::int64_t>::max(), "",
                   "stop after this many cycles (0: until done or SIGTERM)");
  // Up to a day: a sensor silent that long is not coming up.
  tool.add_number("--sensor-wait-s", sensor_wait_s, {0.1, 86400.0, "s"},
                  "start-up: wait this long for depth and attitude")
      ->capture_default_str();
  tool.add_number("--time-scale", time_scale, {0.01, 1000.0, ""},
                  "bench/HIL only (board file: bench = true): the loop clock runs this many times faster")
      ->capture_default_str();
  tool.add_integer("--legs", legs, -2, 100000, "", ".mi: override goto_list num_legs_to_run (-1 loop, -2 once)");
  app.add_flag("--check-mission", check_mission, "read the board and the mission, report, exit (no device opened)");
  std::string slocum_dir;
  std::string sbdlist_path;
  bool no_slocum = false;
  bool slocum_lz4 = false;
  app.add_option("--slocum-dir", slocum_dir,
                 "where the Slocum data files go (.dbd, .sbd, cac/; default: slocum/ beside the flight log)");
  app.add_option("--sbdlist", sbdlist_path, "the .sbd's sensors and decimation (sbdlist.dat; default: built in)")
      ->check(CLI::ExistingFile);
  app.add_flag("--slocum-lz4", slocum_lz4, "write the Slocum files' LZ4 forms (.dcd, .scd, cac/*.ccc), as a G3S");
  app.add_flag("--no-slocum", no_slocum, "write no Slocum data files (the CSV flight log only)");
  app.add_flag("--no-realtime", no_realtime, "do not ask for SCHED_FIFO or mlockall whatever the board says");
  return tool.run(argc, argv, [&]() -> int {
    target::block_stop_signals();  // before the log's writer thread exists
    std::FILE* out = stderr;       // journald takes stderr under systemd
    target::TargetBoard board = target::load_target_board(board_path);
    if (time_scale != 1.0 && !board.bench) {
      throw cli::ToolError(cli::kUsage, "--time-scale is a bench/HIL option: " + board.source +
                                            " is a flight board (it does not say bench = true)");
    }
    // The flight application's mission setup, exactly as glider-sil does it.
    fw::app::MissionOptions mission_options = board.mission_options;
    mission_options.legs = legs;
    const fw::app::PreparedMission prepared = fw::app::prepare_mission(mission_path, board.vehicle, mission_options);
    const std::vector<std::string> messages = fw::app::mission_messages(prepared, false);
    for (std::size_t i = 0; i + (prepared.config ? 0 : 1) < messages.size(); ++i) {
      std::fprintf(out, "%s\n", messages[i].c_str());
    }
    if (!prepared.config) return tool.fail(cli::kError, prepared.refusal);
    if (no_slocum && (!slocum_dir.empty() || !sbdlist_path.empty() || slocum_lz4)) {
      throw cli::ToolError(cli::kUsage, "--no-slocum contradicts --slocum-dir/--sbdlist/--slocum-lz4");
    }
    const fw::SlocumListResult sbdlist = sbdlist_path.empty()
                                             ? fw::parse_slocum_list(fw::kDefaultSbdList, "built-in sbdlist.dat")
                                             : fw::read_slocum_list(sbdlist_path);
    if (!sbdlist.error.empty()) return tool.fail(cli::kError, sbdlist.error);
    // Fitted from the board file: a [gpio] board gives the leak line and the drop weight's burn wire.
    const bool drop_weight_fitted = prepared.config->aborts.drop_weight_fitted;
    if (check_mission) {
      std::fprintf(out, "glider-firmware: %s: mission accepted for board %s\n", mission_path.c_str(),
                   board.name.c_str());
      std::fprintf(out, "glider-firmware: drop weight: %s\n",
                   drop_weight_fitted ? "fitted, released by every abort" : "not fitted (the board has no [gpio])");
      return cli::kOk;
    }
    target::LinuxHalOptions options;
    options.actuators_tcp = actuators_tcp;
    options.time_scale = time_scale;
    if (log_path.empty()) {
      std::filesystem::create_directories(board.log_directory);
      log_path = default_log_name(board.log_directory);
    }
    options.log_path = log_path;
    // The Slocum data files: on unless --no-slocum (the shore's tools read
    // only these), beside the flight log, written by the log's writer thread.
    std::optional<fw::SlocumDirectorySink> slocum_sink;
    std::optional<fw::SlocumLz4Sink> slocum_compressed;
    std::optional<fw::SlocumLogger> slocum;
    if (!no_slocum) {
      if (slocum_dir.empty()) slocum_dir = (std::filesystem::path(log_path).parent_path() / "slocum").string();
      slocum_sink.emplace(slocum_dir);
      if (!slocum_sink->ok()) return tool.fail(cli::kError, slocum_sink->error());
      const fw::SlocumMissionNumbers numbers = fw::next_slocum_mission(slocum_dir, board.name, utc_now_us());
      fw::SlocumLogOptions slocum_options;
      slocum_options.vehicle = board.name;
      slocum_options.mission_name = std::filesystem::path(mission_path).filename().string();
      slocum_options.mission_of_day = numbers.mission_of_day;
      slocum_options.mission_number = numbers.mission_number;
      slocum_options.sbd = sbdlist.selection;
      if (slocum_lz4) slocum_compressed.emplace(*slocum_sink);
      slocum.emplace(slocum_compressed ? static_cast<fw::SlocumSink&>(*slocum_compressed) : *slocum_sink,
                     slocum_options);
      if (!slocum->start()) return tool.fail(cli::kError, slocum_dir + ": " + slocum->error());
      options.slocum = &*slocum;
    }
    options.log_metadata = {{"source", "glider-firmware on the Linux target"},
                            {"board_file", board.source},
                            {"mission_file", mission_path},
                            {"time",
                             "m_present_time is the loop clock told in UTC: UTC seconds (system clock) at the first "
                             "row plus the loop time since (monotonic; simulated seconds at a time scale); "
                             "m_gps_utc_s is the GPS receiver's own UTC of a fresh fix"},
                            {"conventions", "Slocum names, units and signs"}};
    if (time_scale != 1.0) options.log_metadata.emplace_back("time_scale", std::to_string(time_scale));
    std::unique_ptr<target::LinuxHal> linux_hal = target::LinuxHal::build(board, options, out);
    if (no_realtime) board.loop.sched_fifo = board.loop.lock_memory = false;
    const std::string warning = target::apply_realtime(board.loop);
    if (!warning.empty()) std::fprintf(out, "glider-firmware: warning: %s\n", warning.c_str());

    const hal::Hal hal = linux_hal->hal();
    if (const std::string silent = wait_for_sensors(hal, *linux_hal, sensor_wait_s); !silent.empty()) {
      linux_hal->log().close("stopped sensor_wait");
      linux_hal->print_statistics(out);
      return tool.fail(cli::kError, silent);
    }
    PlatformCycle platform(*linux_hal);
    // The log goes through the comms task's tap when the board has a modem.
    fw::comms::LogForward log_forward(hal.log);
    const hal::Hal flight_hal{.clock = hal.clock,
                              .depth = hal.depth,
                              .attitude = hal.attitude,
                              .pump = hal.pump,
                              .battery = hal.battery,
                              .log = log_forward,
                              .rudder = hal.rudder,
                              .gps = hal.gps,
                              .leak = hal.leak,
                              .drop_weight = hal.drop_weight,
                              .power = hal.power};
    fw::app::FlightApplication application(flight_hal, *prepared.config, &platform);
    if (!application.valid()) return tool.fail(cli::kError, "invalid task table");
    const fw::FlightSoftware& flight = application.flight();
    std::optional<hal_linux::SerialModem> modem;
    std::optional<fw::app::MissionFileReloader> reloader;
    std::optional<fw::comms::CommsTask> comms;
    // Zmodem: send from the Slocum folder (never its open segment), receive into its from-shore/.
    struct OpenSegments final : fw::comms::OpenFiles {
      const fw::SlocumDirectorySink* sink = nullptr;
      bool is_open(const char* name) const override { return sink != nullptr && sink->is_open(name); }
    } open_segments;
    // The log's writer thread: a call waits for the rows up to its surfacing (the segment closed then).
    struct WriterProgress final : fw::comms::LogProgress {
      target::RingBufferLog* log = nullptr;
      bool written_through(hal::Micros time_us) override {
        if (log->written_through_us() >= time_us) return true;
        log->wake_writer();
        return false;
      }
    } writer_progress;
    writer_progress.log = &linux_hal->log();
    std::optional<fw::comms::PosixFileAccess> outgoing_files, incoming_files;
    std::optional<fw::comms::ZmodemTransfer> zmodem;
    const std::string incoming_dir = slocum_dir + "/from-shore";
    if (board.modem && slocum_sink) {
      std::error_code ec;
      std::filesystem::create_directories(incoming_dir, ec);
      if (ec) return tool.fail(cli::kError, incoming_dir + ": cannot create: " + ec.message());
      open_segments.sink = &*slocum_sink;
      outgoing_files.emplace(slocum_dir);
      incoming_files.emplace(incoming_dir);
      zmodem.emplace(slocum_dir.c_str(), *outgoing_files, incoming_dir.c_str(), *incoming_files, &open_segments);
    }
    if (board.modem) {
      modem.emplace(board.modem->line);
      reloader.emplace(mission_path, board.vehicle, mission_options);
      // Control-F and zr parse mission files in flight: from this arena, not the heap.
      if (!fw::app::reload_arena::reserve(fw::app::kReloadArenaBytes)) {
        return tool.fail(cli::kError, "cannot reserve the mission reload arena");
      }
      comms.emplace(application.flight(), *modem, hal.gps, hal.log,
                    comms_config(*board.modem, *prepared.config, mission_path, hal.clock.now_us()),
                    zmodem ? &*zmodem : nullptr, &*reloader);
      comms->set_log_progress(&writer_progress);
      log_forward.retarget(*comms);
      application.attach_comms(*comms);
    }
    // Done when the mission is and the last call is over (or the pilot asked for `exit reset`).
    const auto calls_over = [&] { return !comms || comms->idle() || comms->state() == fw::comms::CommsState::kDone; };
    std::fprintf(out, "glider-firmware: board %s, mission %s, flight log %s%s; flying\n", board.name.c_str(),
                 mission_path.c_str(), log_path.c_str(),
                 time_scale != 1.0 ? (", time scale x" + std::to_string(time_scale)).c_str() : "");
    std::fflush(out);

    target::StopReason reason = target::StopReason::kError;
    try {
      target::RealtimeLoop loop(application.executive(), linux_hal->clock(), board.loop, out);
      // The cycles of a transfer, kept apart: their lateness is what a call costs the loop.
      loop.set_tagged([&comms] { return comms && comms->transferring(); });
      std::uint32_t overruns_seen = 0;
      reason = loop.run([&] { return (flight.complete() || (comms && comms->reset_requested())) && calls_over(); },
                        [&] {
                          const bool healthy = application.executive().stats().overruns == overruns_seen;
                          overruns_seen = application.executive().stats().overruns;
                          return healthy;
                        },
                        max_cycles);
      char line[256];
      loop.timing().format(line, sizeof line);
      std::fprintf(out, "glider-firmware: loop: %s; watchdog %s (%llu pings)\n", line,
                   loop.watchdog_enabled() ? "on" : "off", static_cast<unsigned long long>(loop.watchdog_pings()));
      print_transfer_lateness(loop.tagged_lateness_us(), out);
    } catch (const std::exception& error) {
      std::fprintf(out, "glider-firmware: %s\n", error.what());
    }
    const bool aborted = flight.phase() == fw::Phase::kAbort;
    const char* why = reason == target::StopReason::kSignal  ? "stopped by signal"
                      : reason == target::StopReason::kDone  ? "done"
                      : reason == target::StopReason::kError ? "loop error"
                                                             : "cycle limit";
    const std::string outcome = aborted ? std::string("aborted ") + fw::cause_id(flight.abort_cause())
                                : reason == target::StopReason::kDone       ? std::string("complete")
                                : reason == target::StopReason::kSignal     ? std::string("stopped signal")
                                : reason == target::StopReason::kCycleLimit ? std::string("stopped cycle_limit")
                                                                            : std::string("stopped loop_error");
    const bool log_ok = linux_hal->log().close(outcome);
    // The rows lost are the log's count (ring full + disk full), said the same
    // in both summary lines: the flight only sees the ring's refusals.
    const unsigned long long log_lost = static_cast<unsigned long long>(linux_hal->log().rows_refused()) +
                                        static_cast<unsigned long long>(linux_hal->log().rows_lost_disk());
    std::fprintf(out, "glider-firmware: %s; phase %s, %d yos, abort cause %s, %llu log rows lost\n", why,
                 fw::to_string(flight.phase()), flight.yos_completed(), fw::to_string(flight.abort_cause()), log_lost);
    std::fprintf(out, "glider-firmware: drop weight: %s\n",
                 !drop_weight_fitted             ? "not fitted (the board has no [gpio])"
                 : flight.drop_weight_released() ? "released"
                                                 : "fitted, not released");
    bool slocum_ok = true;
    if (slocum) {  // the log's writer thread has stopped: the last rows are in
      slocum_ok = slocum->finish();
      const std::uint64_t slocum_lost = slocum->dbd().cycles_lost + slocum->sbd().cycles_lost;
      std::fprintf(
          out,
          "glider-firmware: slocum files %s: %d segments, .dbd %llu cycles, .sbd %llu cycles, %llu lost, %llu values "
          "not representable\n",
          slocum_dir.c_str(), slocum->segments(), static_cast<unsigned long long>(slocum->dbd().cycles_written),
          static_cast<unsigned long long>(slocum->sbd().cycles_written), static_cast<unsigned long long>(slocum_lost),
          static_cast<unsigned long long>(slocum->unrepresentable()));
      if (!slocum_ok)
        std::fprintf(out, "glider-firmware: %s: writing the Slocum files lost rows\n", slocum_dir.c_str());
    }
    std::fprintf(out, "glider-firmware: flight log %s: %llu rows, %llu lost (ring full %llu, disk %llu), %llu fsyncs\n",
                 log_path.c_str(), static_cast<unsigned long long>(linux_hal->log().rows_written()), log_lost,
                 static_cast<unsigned long long>(linux_hal->log().rows_refused()),
                 static_cast<unsigned long long>(linux_hal->log().rows_lost_disk()),
                 static_cast<unsigned long long>(linux_hal->log().fsyncs()));
    linux_hal->print_statistics(out);
    if (comms) {
      const fw::comms::CommsStats& c = comms->stats();
      std::fprintf(out,
                   "glider-firmware: comms: %u surfacings, %u calls connected (%u dialled), %u without a call, %u "
                   "carrier drops, %llu bytes sent, %llu received\n",
                   c.surfacings, c.calls_connected, c.dial_attempts, c.surfacings_without_call, c.carrier_drops,
                   static_cast<unsigned long long>(c.bytes_sent), static_cast<unsigned long long>(c.bytes_received));
    }
    if (!log_ok) std::fprintf(out, "glider-firmware: %s: writing the flight log failed\n", log_path.c_str());
    if (reason == target::StopReason::kError || !log_ok || !slocum_ok) return static_cast<int>(cli::kError);
    // The pilot's `exit reset`: systemd starts the firmware again (RestartForceExitStatus=4).
    if (comms && comms->reset_requested()) {
      std::fprintf(out, "glider-firmware: exit reset: restarting\n");
      return kExitReset;
    }
    // A clean stop (SIGTERM: systemctl stop) is success; an abort or the
    // cycle limit ends the flight early (systemd must not restart either).
    if (aborted || reason == target::StopReason::kCycleLimit) return static_cast<int>(cli::kStopped);
    return static_cast<int>(cli::kOk);
  });
}
