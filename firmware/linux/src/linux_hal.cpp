// SPDX-License-Identifier: Apache-2.0
#include "glider/target/linux_hal.hpp"

#include <stdexcept>

namespace glider::target {
namespace {

std::unique_ptr<hal_linux::ModbusLink> open_link(const hal_linux::BusConfig& bus, const std::string& what,
                                                 std::FILE* log) {
  std::string warning;
  std::string error;
  auto link = hal_linux::ModbusLink::open(bus, warning, error);
  if (!link) throw std::runtime_error(what + " (" + hal_linux::describe(bus) + "): " + error);
  if (!warning.empty()) std::fprintf(log, "glider-firmware: %s: %s\n", what.c_str(), warning.c_str());
  if (!link->connected()) {
    std::fprintf(log, "glider-firmware: %s (%s): not connected yet, retrying every cycle\n", what.c_str(),
                 hal_linux::describe(bus).c_str());
  }
  return link;
}

std::unique_ptr<hal_linux::SerialPort> open_port(const SerialSensorConfig& sensor, const std::string& what) {
  try {
    return hal_linux::SerialPort::open(sensor.device, sensor.baud);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(what + ": " + error.what());
  }
}

void print_sentences(std::FILE* out, const char* name, const hal_linux::SentenceStats& s, std::uint64_t stale,
                     const hal_linux::NmeaSerialStream& stream) {
  std::fprintf(out,
               "glider-firmware: %s: %llu bytes, %llu sentences used; rejected: %llu bad checksum, %llu no "
               "checksum, %llu malformed, %llu implausible, %llu no fix; %llu garbage bytes, %llu overlong; "
               "%llu stale reads\n",
               name, static_cast<unsigned long long>(stream.port_stats().bytes),
               static_cast<unsigned long long>(s.accepted), static_cast<unsigned long long>(s.bad_checksum),
               static_cast<unsigned long long>(s.no_checksum), static_cast<unsigned long long>(s.malformed),
               static_cast<unsigned long long>(s.implausible), static_cast<unsigned long long>(s.no_fix),
               static_cast<unsigned long long>(stream.framer_stats().garbage_bytes),
               static_cast<unsigned long long>(stream.framer_stats().overlong), static_cast<unsigned long long>(stale));
}

}  // namespace

std::unique_ptr<LinuxHal> LinuxHal::build(const TargetBoard& board, const LinuxHalOptions& options, std::FILE* log) {
  std::unique_ptr<LinuxHal> h(new LinuxHal());
  h->clock_ = LoopClock(options.time_scale);  // before any device holds it
  // GPIO first: a wrong board file is the quickest thing to find out.
  if (board.gpio_board) {
    h->gpio_ = hal_linux::GpioLines::open(hal_linux::load_gpio_board(*board.gpio_board), h->clock_);
  } else {
    std::fprintf(log, "glider-firmware: %s: no [gpio] board: NO leak detection and NO drop weight (bench use only)\n",
                 board.source.c_str());
  }
  h->actuator_board_ = hal_linux::load_modbus_board(board.actuators_board);
  if (!options.actuators_tcp.empty()) hal_linux::use_tcp_endpoint(h->actuator_board_.bus, options.actuators_tcp);
  h->actuator_link_ = open_link(h->actuator_board_.bus, "actuators", log);
  h->pump_axis_ = std::make_unique<hal_linux::ModbusAxis>(*h->actuator_link_, h->actuator_board_.pump);
  h->slide_axis_ = std::make_unique<hal_linux::ModbusAxis>(*h->actuator_link_, h->actuator_board_.slide);
  h->pump_ = std::make_unique<hal_linux::ModbusBuoyancyPump>(*h->pump_axis_, h->clock_);
  h->slide_ = std::make_unique<hal_linux::ModbusBatterySlide>(*h->slide_axis_, h->clock_);
  if (h->actuator_board_.rudder) {
    h->rudder_axis_ = std::make_unique<hal_linux::ModbusAxis>(*h->actuator_link_, *h->actuator_board_.rudder);
    h->rudder_ = std::make_unique<hal_linux::ModbusRudder>(*h->rudder_axis_, h->clock_);
  }
  if (board.power) {
    h->power_ = hal_linux::HwmonPowerMonitor::open(*board.power, h->clock_);
  } else {
    std::fprintf(log, "glider-firmware: %s: no [power] monitor: no battery voltage or charge readings\n",
                 board.source.c_str());
  }
  h->depth_link_ = open_link(board.depth.bus, "depth transmitter", log);
  h->depth_ = std::make_unique<hal_linux::KellerDepthSensor>(*h->depth_link_, board.depth.keller, h->clock_);
  h->gps_ =
      std::make_unique<hal_linux::NmeaGpsReceiver>(open_port(board.gps, "gps"), h->clock_, board.gps.stale_after_us);
  h->compass_ = std::make_unique<hal_linux::SerialCompass>(open_port(board.compass, "compass"), h->clock_,
                                                           board.compass.stale_after_us);
  RingLogOptions log_options;
  log_options.metadata = options.log_metadata;
  log_options.messages = log;
  log_options.loop_clock = &h->clock_;
  log_options.slocum = options.slocum;
  h->log_ = std::make_unique<RingBufferLog>(options.log_path, std::move(log_options));
  return h;
}

hal::Hal LinuxHal::hal() {
  hal::Rudder& rudder = rudder_ ? static_cast<hal::Rudder&>(*rudder_) : fixed_rudder_;
  hal::DigitalInput* leak_line = leak();
  hal::DigitalOutput* drop_line = drop_weight();
  hal::PowerMonitor& power_monitor = power_ ? static_cast<hal::PowerMonitor&>(*power_) : no_power_;
  return hal::Hal{.clock = clock_,
                  .depth = *depth_,
                  .attitude = *compass_,
                  .pump = *pump_,
                  .battery = *slide_,
                  .log = *log_,
                  .rudder = rudder,
                  .gps = *gps_,
                  .leak = leak_line != nullptr ? *leak_line : static_cast<hal::DigitalInput&>(no_leak_),
                  .drop_weight = drop_line != nullptr ? *drop_line : static_cast<hal::DigitalOutput&>(no_drop_weight_),
                  .power = power_monitor};
}

void LinuxHal::begin_cycle() noexcept {
  actuator_link_->begin_cycle();
  depth_link_->begin_cycle();
}

hal::DigitalInput* LinuxHal::leak() { return gpio_ ? gpio_->input(hal_linux::LineRole::kLeak) : nullptr; }
hal::DigitalOutput* LinuxHal::drop_weight() {
  return gpio_ ? gpio_->output(hal_linux::LineRole::kDropWeight) : nullptr;
}

void LinuxHal::print_statistics(std::FILE* out) const {
  print_sentences(out, "gps", gps_->stats(), gps_->stale_reads(), gps_->stream());
  print_sentences(out, "compass", compass_->stats(), compass_->stale_reads(), compass_->stream());
  const auto& d = depth_->stats();
  std::fprintf(
      out, "glider-firmware: depth: %llu reads; rejected: %llu bus failures, %llu channel errors, %llu out of range\n",
      static_cast<unsigned long long>(d.reads), static_cast<unsigned long long>(d.bus_failures),
      static_cast<unsigned long long>(d.channel_errors), static_cast<unsigned long long>(d.out_of_range));
  for (const auto* link : {actuator_link_.get(), depth_link_.get()}) {
    const auto& s = link->stats();
    std::fprintf(out,
                 "glider-firmware: modbus %s: %llu transactions, %llu failed, %llu budget refusals, %llu reconnects\n",
                 hal_linux::describe(link->bus()).c_str(), static_cast<unsigned long long>(s.transactions),
                 static_cast<unsigned long long>(s.failed), static_cast<unsigned long long>(s.budget_refusals),
                 static_cast<unsigned long long>(s.reconnects));
  }
  if (power_) {
    const auto& p = power_->stats();
    std::fprintf(out, "glider-firmware: power %s: %llu reads; rejected: %llu errors, %llu out of range\n",
                 power_->device().c_str(), static_cast<unsigned long long>(p.reads),
                 static_cast<unsigned long long>(p.errors), static_cast<unsigned long long>(p.out_of_range));
  }
  std::fprintf(out, "glider-firmware: log: %llu rows written, %llu refused (ring full)\n",
               static_cast<unsigned long long>(log_->rows_written()),
               static_cast<unsigned long long>(log_->rows_refused()));
}

}  // namespace glider::target
