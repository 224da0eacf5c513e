// SPDX-License-Identifier: Apache-2.0
#include "plant.hpp"

#include <signal.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>

#include "board_files.hpp"
#include "glider/hal_linux/register_map.hpp"
#include "glider/model/simulator.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/sim_hal.hpp"
#include "glider/target/loop_timing.hpp"
#include "glider/units.hpp"
#include "keller_server.hpp"
#include "lateness_record.hpp"
#include "modem_bridge.hpp"
#include "nmea_sentences.hpp"
#include "plant_axis.hpp"
#include "pty_device.hpp"

namespace glider::plant {
namespace {

namespace regs = hal_linux::regs;
using Clock = std::chrono::steady_clock;

// The plant's real-time tick: the actuator axes, the sensors and the model
// advance this often (the model's own steps are at most this long then).
constexpr double kStepS = 0.1;
constexpr hal::Micros kStepUs = 100'000;
constexpr double kStandardGravity = 9.80665;   // as the firmware's Keller driver converts
constexpr double kUtcAtLaunchS = 12 * 3600.0;  // the NMEA time of day (the firmware does not use it)

int open_stop_signals() {
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGTERM);
  sigaddset(&stop, SIGINT);
  sigprocmask(SIG_BLOCK, &stop, nullptr);
  const int fd = signalfd(-1, &stop, SFD_NONBLOCK | SFD_CLOEXEC);
  if (fd < 0) throw std::runtime_error("signalfd failed");
  return fd;
}

class Plant {
 public:
  Plant(const PlantOptions& options, std::FILE* out);
  ~Plant();
  void run();

 private:
  bool writable(int address) const;
  void check_vehicle_fits_axes() const;
  void take_commands();
  void step();
  void apply_due_faults();
  void apply(const PlantFault& fault);
  void send_sentences();
  KellerReading measure_depth();
  void write_truth();
  void print_statistics(const char* why);

  const PlantOptions& options_;
  std::FILE* out_;
  hal_linux::ModbusBoard board_;
  model::GliderSimulator sim_;
  sil::SimClock clock_;
  std::unique_ptr<sil::SimHal> sensors_;
  std::vector<PlantAxis> axes_;
  modbus_mapping_t* mapping_ = nullptr;
  std::unique_ptr<ModbusTcpServer> tcp_;
  std::unique_ptr<PtyDevice> gps_line_;
  std::unique_ptr<PtyDevice> compass_line_;
  std::unique_ptr<PtyDevice> depth_line_;
  std::unique_ptr<KellerServer> keller_;
  std::unique_ptr<ModemBridge> modem_;
  std::unique_ptr<LatenessRecord> lateness_;
  hal_linux::KellerConfig keller_config_;
  std::ofstream truth_;
  int signal_fd_ = -1;

  bool launched_ = false;
  std::uint64_t steps_ = 0;
  std::vector<bool> fault_applied_;
  bool depth_silent_ = false;
  bool compass_silent_ = false;
  bool gps_silent_ = false;
  double last_fin_rad_ = 0.0;
  hal::Micros last_fix_sent_us_ = -1;
  double next_truth_s_ = 0.0;
  target::LoopTiming timing_;  // the firmware loop's statistics, for the plant's steps
};

Plant::Plant(const PlantOptions& options, std::FILE* out)
    : options_(options),
      out_(out),
      board_(hal_linux::load_modbus_board(options.actuator_board)),
      sim_(options.vehicle, options.environment),
      fault_applied_(options.faults.size(), false) {
  const double start_cc = std::clamp(m3_to_cc(options.vehicle.ballast.volume_max_m3), board_.pump.min, board_.pump.max);
  sim_.reset_at_surface(cc_to_m3(start_cc), 0.0, deg_to_rad(options.heading_deg));
  sensors_ = std::make_unique<sil::SimHal>(sim_, clock_, sil::SensorNoise{}, options.seed);

  axes_.emplace_back(board_.pump, start_cc);
  axes_.emplace_back(board_.slide, 0.0);
  if (board_.rudder) axes_.emplace_back(*board_.rudder, 0.0);
  int size = 0;
  for (const PlantAxis& axis : axes_) {
    if (axis.slave() != axes_.front().slave()) {
      throw std::runtime_error(board_.source + ": the plant serves one slave id: give every axis the same slave");
    }
    size = std::max(size, axis.base() + regs::kBlockLength);
  }
  mapping_ = modbus_mapping_new(0, 0, size, 0);
  if (mapping_ == nullptr) throw std::runtime_error("modbus_mapping_new failed");
  for (const PlantAxis& axis : axes_) axis.initial_commands(mapping_->tab_registers + axis.base());
  check_vehicle_fits_axes();

  TcpServerOptions tcp = options.tcp;
  tcp_ = std::make_unique<ModbusTcpServer>(tcp, mapping_, axes_.front().slave(), [this](int a) { return writable(a); });
  std::filesystem::create_directories(options.directory);
  lateness_ = std::make_unique<LatenessRecord>((options.directory / "lateness.csv").string(), options.record_late_ms);
  // Stamped with the simulated time of the step before the read: a stalled
  // plant answers before it steps again, so the row falls where the stall began.
  tcp_->set_answer_observer(
      [this](double late_ms, int requests) { lateness_->answer(sim_.time_s(), late_ms, requests); });
  gps_line_ = std::make_unique<PtyDevice>((options.directory / "gps").string());
  compass_line_ = std::make_unique<PtyDevice>((options.directory / "compass").string());
  depth_line_ = std::make_unique<PtyDevice>((options.directory / "depth").string());
  keller_ = std::make_unique<KellerServer>(depth_line_->master_fd(), depth_line_->link(), keller_config_.slave);

  PlantEndpoints endpoints;
  endpoints.host = tcp.host;
  endpoints.port = tcp_->port();
  endpoints.gps_device = gps_line_->link();
  endpoints.compass_device = compass_line_->link();
  endpoints.depth_device = depth_line_->link();
  endpoints.keller = keller_config_;
  if (options.shore_port > 0) {
    modem_ = std::make_unique<ModemBridge>((options.directory / "modem").string(), options.shore_host,
                                           options.shore_port, options.time_scale);
    endpoints.modem_device = modem_->link();
    endpoints.modem_vehicle_name = options.vehicle_name.empty() ? options.vehicle.name : options.vehicle_name;
  }
  endpoints.log_directory = options.directory / "logs";
  endpoints.vehicle = sil::vehicle_setup(options.vehicle, fw::app::FittedDevices{}, options.max_working_depth_m, false,
                                         options.environment.water.at(0.0, 0.0).density_kg_m3);
  endpoints.heading_law = options.heading_law;
  const auto board_file = write_board_files(options.directory, board_, endpoints);

  if (!options.truth_path.empty()) {
    truth_.open(options.truth_path);
    if (!truth_) throw std::runtime_error(options.truth_path + ": cannot write");
    truth_ << "time_s,east_m,north_m,depth_m,heading_deg,pitch_deg,pumped_cc,battpos_in,fin_deg\n";
  }
  signal_fd_ = open_stop_signals();
  std::fprintf(out_,
               "glider-plant: ready: board %s; modbus tcp %s, depth %s, gps %s, compass %s; vehicle %s, seed %llu, "
               "time scale %g\n",
               board_file.c_str(), tcp_->endpoint().c_str(), depth_line_->link().c_str(), gps_line_->link().c_str(),
               compass_line_->link().c_str(), options.vehicle.name.c_str(),
               static_cast<unsigned long long>(options.seed), options.time_scale);
  std::fflush(out_);
}

Plant::~Plant() {
  if (signal_fd_ >= 0) close(signal_fd_);
  keller_.reset();
  tcp_.reset();
  if (mapping_ != nullptr) modbus_mapping_free(mapping_);
}

// The board's [vehicle] (the model's travel and fin limit) is what the
// firmware commands up to; an axis whose command limits are narrower would
// refuse those commands, an actuator fault at the first full stroke.
void Plant::check_vehicle_fits_axes() const {
  const model::VehicleParams& v = options_.vehicle;
  const auto check = [&](const hal_linux::AxisConfig& axis, double lo, double hi) {
    if (lo < axis.min - 1e-9 || hi > axis.max + 1e-9) {
      throw std::runtime_error(board_.source + ": " + axis.name + " command limits [" + std::to_string(axis.min) +
                               ", " + std::to_string(axis.max) + "] " + axis.unit + " are narrower than vehicle " +
                               v.name + "'s [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
  };
  check(board_.pump, m3_to_cc(v.ballast.volume_min_m3), m3_to_cc(v.ballast.volume_max_m3));
  check(board_.slide, m_to_in(v.battery.travel_min_m), m_to_in(v.battery.travel_max_m));
  if (board_.rudder) check(*board_.rudder, -rad_to_deg(v.heading.fin_max_rad), rad_to_deg(v.heading.fin_max_rad));
}

bool Plant::writable(int address) const {
  for (const PlantAxis& axis : axes_) {
    const int offset = address - axis.base();
    if (offset >= 0 && offset < regs::kBlockLength) return offset >= regs::kControl && offset <= regs::kSpeed;
  }
  return false;  // between the axes' blocks: nothing there to write
}

void Plant::take_commands() {
  for (PlantAxis& axis : axes_) {
    std::uint16_t* block = mapping_->tab_registers + axis.base();
    axis.take_commands(block);
    if (!launched_ && (block[regs::kControl] & regs::kEnable) != 0) {
      launched_ = true;
      std::fprintf(out_, "glider-plant: launch: first actuator command (%s), model released\n",
                   axis.config().name.c_str());
      std::fflush(out_);
    }
  }
}

void Plant::apply(const PlantFault& fault) {
  const auto jam = [&](const std::string& name) {
    for (PlantAxis& axis : axes_) {
      if (axis.config().name == name) axis.jam();
    }
  };
  switch (fault.kind) {
    case PlantFaultKind::kPumpStall:
      jam("pump");
      break;
    case PlantFaultKind::kSlideStall:
      jam("slide");
      break;
    case PlantFaultKind::kRudderStall:
      jam("rudder");
      break;
    case PlantFaultKind::kDepthSilent:
      depth_silent_ = true;
      break;
    case PlantFaultKind::kCompassSilent:
      compass_silent_ = true;
      break;
    case PlantFaultKind::kGpsSilent:
      gps_silent_ = true;
      break;
    case PlantFaultKind::kPlantSilent:
      depth_silent_ = compass_silent_ = gps_silent_ = true;
      tcp_->set_silent(true);
      break;
  }
  std::fprintf(out_, "glider-plant: fault %s at %.1f s after launch\n", fault.name.c_str(), sim_.time_s());
  std::fflush(out_);
}

void Plant::apply_due_faults() {
  for (std::size_t i = 0; i < options_.faults.size(); ++i) {
    if (!fault_applied_[i] && sim_.time_s() >= options_.faults[i].at_s) {
      fault_applied_[i] = true;
      apply(options_.faults[i]);
    }
  }
}

KellerReading Plant::measure_depth() {
  const hal::DepthSample sample = sensors_->read();  // the model's depth with the SIL's noise
  const double pressure_bar = keller_config_.surface_pressure_bar +
                              sample.depth_m * keller_config_.water_density_kg_m3 * kStandardGravity / 1e5;
  return {std::max(pressure_bar, 0.0), sim_.truth().water.temperature_c};
}

void Plant::send_sentences() {
  const double utc = kUtcAtLaunchS + sim_.time_s();
  const std::uint64_t compass_every = std::max<std::uint64_t>(1, std::llround(options_.compass_interval_s / kStepS));
  if (!compass_silent_ && steps_ % compass_every == 0) {
    compass_line_->write_newest(ptnthpr(sensors_->attitude().read()));
  }
  // The receiver computes once a second (the model's fix interval), and the
  // model is asked at whole seconds after launch, the instants glider-sil's
  // firmware asks it at: sampled faster or at other instants, the surface
  // bobbing would restart its acquisition (a new time to first fix) otherwise.
  const bool whole_second = launched_ ? clock_.now_us() % 1'000'000 == 0 : steps_ % 10 == 0;
  if (gps_silent_ || !whole_second) return;
  const hal::GpsFix fix = sensors_->gps().read();
  if (fix.valid && fix.time_us != last_fix_sent_us_) {
    gps_line_->write_all_or_drop(gga_fix(fix, utc) + rmc_fix(fix, utc));
    last_fix_sent_us_ = fix.time_us;
  } else {
    gps_line_->write_all_or_drop(gga_no_fix(utc));  // a receiver without sky still talks
  }
}

void Plant::write_truth() {
  if (!truth_.is_open() || sim_.time_s() + 1e-9 < next_truth_s_) return;
  const model::Truth t = sim_.truth();
  char row[256];
  std::snprintf(row, sizeof row, "%.1f,%.3f,%.3f,%.3f,%.2f,%.2f,%.1f,%.3f,%.2f\n", t.time_s, t.east_m, t.north_m,
                t.depth_m, rad_to_deg(t.heading_rad), rad_to_deg(t.pitch_rad), m3_to_cc(t.pumped_volume_m3),
                m_to_in(t.battery_pos_m), rad_to_deg(t.fin_rad));
  truth_ << row;
  next_truth_s_ += 1.0;
}

void Plant::step() {
  ++steps_;
  if (launched_) {
    write_truth();
    for (PlantAxis& axis : axes_) axis.step(kStepS, mapping_->tab_registers + axis.base());
    sim_.command_pumped_volume_m3(cc_to_m3(axes_[0].position()));
    sim_.command_battery_pos_m(in_to_m(axes_[1].position()));
    if (axes_.size() > 2 && deg_to_rad(axes_[2].position()) != last_fin_rad_) {
      last_fin_rad_ = deg_to_rad(axes_[2].position());
      sim_.command_fin_rad(last_fin_rad_);
    }
    sim_.advance(kStepS);
    clock_.advance(kStepUs);
    apply_due_faults();
  }
  send_sentences();
}

void Plant::run() {
  const auto step_wall =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kStepS / options_.time_scale));
  const Clock::time_point start = Clock::now();
  std::vector<pollfd> fds;
  fds.reserve(8 + static_cast<std::size_t>(options_.tcp.max_clients));
  const char* why = "signal";
  for (std::uint64_t k = 1;; ++k) {
    const Clock::time_point deadline = start + step_wall * static_cast<std::int64_t>(k);
    bool stop = false;
    // Serve the devices until the step's deadline (at least one look).
    while (true) {
      fds.clear();
      fds.push_back({signal_fd_, POLLIN, 0});
      fds.push_back({depth_line_->master_fd(), POLLIN, 0});
      const std::size_t modem_at = fds.size();
      if (modem_) modem_->append_pollfds(fds);
      const std::size_t tcp_at = fds.size();
      tcp_->append_pollfds(fds);
      const auto left = deadline - Clock::now();
      const auto left_ns =
          std::max<std::int64_t>(0, std::chrono::duration_cast<std::chrono::nanoseconds>(left).count());
      timespec timeout{static_cast<time_t>(left_ns / 1'000'000'000), static_cast<long>(left_ns % 1'000'000'000)};
      const int ready = ppoll(fds.data(), fds.size(), &timeout, nullptr);
      if (ready > 0) {
        if ((fds[0].revents & POLLIN) != 0) stop = true;
        if ((fds[1].revents & POLLIN) != 0) keller_->on_readable([this] { return measure_depth(); }, depth_silent_);
        tcp_->service(fds.data() + tcp_at, fds.size() - tcp_at, [this] { take_commands(); });
      }
      if (modem_) modem_->service(fds.data() + modem_at, tcp_at - modem_at);
      const Clock::time_point now = Clock::now();
      tcp_->expire(now);
      if (stop || now >= deadline) break;
    }
    if (stop) break;
    const Clock::time_point woke = Clock::now();
    const double stalled_at_s = sim_.time_s();
    step();
    const auto us = [](Clock::duration d) { return std::chrono::duration_cast<std::chrono::microseconds>(d).count(); };
    timing_.record(us(woke - deadline), us(Clock::now() - woke), us(step_wall));
    lateness_->step(stalled_at_s, static_cast<double>(us(woke - deadline)) / 1000.0);
    if (launched_ && options_.duration_s > 0.0 && sim_.time_s() >= options_.duration_s) {
      why = "duration reached";
      break;
    }
  }
  print_statistics(why);
}

void Plant::print_statistics(const char* why) {
  const TcpServerStats& t = tcp_->stats();
  const model::Truth truth = sim_.truth();
  std::fprintf(
      out_, "glider-plant: stopped (%s); %s; %.1f s simulated after launch, depth %.2f m, east %.1f m, north %.1f m\n",
      why, launched_ ? "launched" : "never launched", sim_.time_s(), truth.depth_m, truth.east_m, truth.north_m);
  char line[256];
  timing_.format(line, sizeof line);
  std::fprintf(out_, "glider-plant: steps: %s (time scale %g)\n", line, options_.time_scale);
  std::fprintf(out_,
               "glider-plant: modbus tcp: %llu connections, %llu refused (cap %d), %llu requests, %llu exceptions, "
               "%llu malformed, %llu timed out, %llu unanswered\n",
               t.accepted, t.refused, options_.tcp.max_clients, t.requests, t.exceptions, t.malformed, t.timed_out,
               t.ignored);
  std::fprintf(out_,
               "glider-plant: depth: %llu requests, %llu rejected; gps %llu, compass %llu bytes dropped; compass %llu "
               "unread bytes discarded for newer\n",
               keller_->requests(), keller_->rejected(), gps_line_->dropped_bytes(), compass_line_->dropped_bytes(),
               compass_line_->discarded_bytes());
  std::fprintf(out_, "glider-plant: lateness: %s; %s\n", lateness_->summary().c_str(),
               (options_.directory / "lateness.csv").c_str());
  if (modem_) {
    const ModemBridgeStats& m = modem_->stats();
    std::fprintf(out_, "glider-plant: modem: %llu calls, %llu connected, %llu bytes up, %llu bytes down\n",
                 static_cast<unsigned long long>(m.calls), static_cast<unsigned long long>(m.connects),
                 static_cast<unsigned long long>(m.bytes_up), static_cast<unsigned long long>(m.bytes_down));
  }
  std::fflush(out_);
}

}  // namespace

void run_plant(const PlantOptions& options, std::FILE* out) {
  if (!(options.time_scale >= 0.01 && options.time_scale <= 1000.0)) {
    throw std::runtime_error("time scale must be in [0.01, 1000]");
  }
  const double steps = options.compass_interval_s / kStepS;
  if (!(steps >= 1.0 - 1e-9 && steps <= 100.0 + 1e-9 && std::fabs(steps - std::round(steps)) < 1e-6)) {
    throw std::runtime_error("compass interval " + std::to_string(options.compass_interval_s) +
                             " s: must be a whole number of model steps (0.1 s) in [0.1, 10] s");
  }
  if (!(options.record_late_ms > 0.0)) throw std::runtime_error("the lateness record's floor must be > 0 ms");
  Plant plant(options, out);
  plant.run();
}

}  // namespace glider::plant
