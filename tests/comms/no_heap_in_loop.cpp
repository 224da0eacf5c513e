// SPDX-License-Identifier: Apache-2.0
// The comms code allocates nothing in the loop: a navigated mission with the
// comms task calling at every surfacing (modem start, signal, dial, dialog
// re-printed, console commands typed, hang-up) with every operator new
// counted. A plain program (not CppUTest); exit status 0 = pass.
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include "fake_hal.hpp"
#include "glider/firmware/comms/comms_task.hpp"

namespace {

std::atomic<unsigned long> g_allocations{0};

void* allocate(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

// A modem with fixed buffers that answers AT, ATE0, AT+CSQ, ATD (CONNECT),
// +++ and ATH, and in a call types a few console commands.
class FixedModem final : public glider::hal::Modem {
 public:
  std::size_t read(std::span<std::uint8_t> buffer) override {
    if (data_ && ++reads_ % 40 == 0 && typed_++ < 6) say("whoru\r!get u_printout_cycle_time\rbogus\r");
    std::size_t n = 0;
    while (n < buffer.size() && head_ < size_) buffer[n++] = out_[head_++];
    if (head_ == size_) head_ = size_ = 0;
    return n;
  }
  std::size_t write(std::span<const std::uint8_t> bytes) override {
    for (const std::uint8_t b : bytes) {
      if (data_) {
        plus_ = b == '+' ? plus_ + 1 : 0;
        if (plus_ == 3) {
          data_ = false;
          say("\r\nOK\r\n");
        }
        continue;
      }
      if (b != '\r') {
        if (line_size_ < sizeof line_ - 1) line_[line_size_++] = static_cast<char>(b);
        continue;
      }
      line_[line_size_] = '\0';
      line_size_ = 0;
      if (std::strcmp(line_, "AT+CSQ") == 0) {
        say("\r\n+CSQ:5\r\n\r\nOK\r\n");
      } else if (std::strncmp(line_, "ATD", 3) == 0) {
        say("\r\nCONNECT 19200\r\n");
        data_ = true;
        ++calls;
      } else {
        say("\r\nOK\r\n");
      }
    }
    return bytes.size();
  }
  glider::hal::Carrier carrier() const override {
    return data_ ? glider::hal::Carrier::kPresent : glider::hal::Carrier::kUnknown;
  }
  int calls = 0;

 private:
  void say(const char* text) {
    for (const char* p = text; *p != '\0' && size_ < out_.size(); ++p) out_[size_++] = static_cast<std::uint8_t>(*p);
  }
  std::array<std::uint8_t, 4096> out_{};
  std::size_t head_ = 0, size_ = 0;
  char line_[64] = {};
  std::size_t line_size_ = 0;
  bool data_ = false;
  int plus_ = 0;
  unsigned reads_ = 0;
  int typed_ = 0;
};

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

int main() {
  using namespace glider;
  test::FakeHal fake;
  fw::FlightSoftwareConfig config;
  config.mission.start_at_launch = false;
  config.mission.yos = 2;
  config.plan.waypoint_count = 2;
  config.plan.waypoints[0] = {54.02, 7.0};
  config.plan.waypoints[1] = {54.04, 7.0};
  config.plan.legs_to_run = 2;
  config.plan.waypoint_radius_m = 500.0;
  config.plan.gps_wait_s = 60.0;
  config.plan.surface_dwell_s = 120.0;
  fw::FlightSoftware flight(fake.hal(), config);
  FixedModem modem;
  fw::comms::CommsConfig comms_config;
  comms_config.gps_wait_s = 30.0;
  comms_config.keystroke_wait_s = 120.0;
  comms_config.printout_cycle_s = 20.0;
  std::snprintf(comms_config.primary_number, sizeof comms_config.primary_number, "0088160000519");
  std::snprintf(comms_config.sensors[0].data(), 40, "m_depth");
  comms_config.sensor_count = 1;
  fw::comms::CommsTask comms(flight, modem, fake.gps, fake, comms_config);

  const unsigned long before = g_allocations.load();
  double north_m = 0.0, depth = 0.5;
  int cycles = 0;
  long dialog_cycles = 0;
  double dialog_sum_us = 0.0, dialog_max_us = 0.0;
  for (; cycles < 100000 && !(flight.complete() && comms.idle()); ++cycles) {
    const fw::Phase phase = flight.phase();
    const bool under_way = phase == fw::Phase::kDive || phase == fw::Phase::kClimb;
    if (under_way) {
      depth += phase == fw::Phase::kDive ? 0.3 : -0.3;
      north_m += 0.3;
    } else {
      depth = 0.2;
    }
    fake.pump_cc = phase == fw::Phase::kDive ? config.mission.dive_ballast_cc : config.mission.climb_ballast_cc;
    fake.depth = {depth, fake.now, true};
    fake.attitude.sample = {phase == fw::Phase::kClimb ? 0.45 : -0.45, 0.0, 0.0, fake.now, true};
    fake.leak.sample.time_us = fake.now;
    fake.power.sample.time_us = fake.now;
    fake.gps.fix = {54.0 + north_m / 111195.0, 7.0, 1, 8, 1.0, fake.now, !under_way};
    flight.run(fake.now);
    (void)comms.write(fake.last_row);  // the tap sees the row (and passes it on to the fake)
    const bool in_dialog = comms.state() == fw::comms::CommsState::kDialog;
    const auto start = std::chrono::steady_clock::now();
    comms.run(fake.now);
    if (in_dialog) {
      const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
      ++dialog_cycles;
      dialog_sum_us += us;
      dialog_max_us = us > dialog_max_us ? us : dialog_max_us;
    }
    if (flight.complete() && comms.state() == fw::comms::CommsState::kDone) break;
    fake.now += 1'000'000;
  }
  const unsigned long during = g_allocations.load() - before;
  const auto& s = comms.stats();
  std::printf(
      "cycles %d, surfacings %u, calls %u (modem %d), dialogs printed %u, console lines %u, bytes sent %llu, "
      "heap allocations in the loop: %lu\n",
      cycles, s.surfacings, s.calls_connected, modem.calls, s.dialogs_printed, comms.console_stats().lines,
      static_cast<unsigned long long>(s.bytes_sent), during);
  std::printf("comms task per cycle in a call: mean %.2f us, max %.1f us over %ld cycles\n",
              dialog_cycles > 0 ? dialog_sum_us / static_cast<double>(dialog_cycles) : 0.0, dialog_max_us,
              dialog_cycles);
  const bool called = s.calls_connected >= 2 && s.dialogs_printed >= 2 && comms.console_stats().lines > 0;
  return called && during == 0 ? 0 : 1;
}
