// SPDX-License-Identifier: Apache-2.0
// Depth from a Keller Series 30 class transmitter over Modbus RTU: the
// driver through ModbusLink on one end of a socat pty pair, a libmodbus
// RTU server holding the transmitter's registers on the other.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <limits>

#include "../modbus/child_process.hpp"
#include "glider/hal_linux/keller_depth.hpp"
#include "keller_transmitter.hpp"

using namespace glider;

namespace {

class ManualClock final : public hal::Clock {
 public:
  hal::Micros now_us() const override { return 7; }
};

hal_linux::BusConfig rtu_bus(const std::string& device) {
  hal_linux::BusConfig bus;
  bus.transport = hal_linux::Transport::kRtu;
  bus.device = device;
  bus.baud = 9600;
  bus.response_timeout_ms = 100;
  bus.retries = 1;
  bus.cycle_budget_ms = 300;
  bus.cycle_period_ms = 1000;
  return bus;
}

}  // namespace

TEST_GROUP(KellerDepth){};

TEST(KellerDepth, FloatsAndHydrostatics) {
  DOUBLES_EQUAL(1.01325, hal_linux::keller_float(0x3F81, 0xB22D), 1e-7);  // 0x3F81B22D
  hal_linux::KellerConfig config;
  DOUBLES_EQUAL(0.0, hal_linux::depth_from_pressure(1.01325, config), 1e-12);
  // 10 m of 1025 kg/m^3 seawater is 1.00518 bar above the atmosphere.
  DOUBLES_EQUAL(10.0, hal_linux::depth_from_pressure(1.01325 + 1025.0 * 9.80665 * 10.0 / 1e5, config), 1e-9);
}

TEST(KellerDepth, DepthOverModbusRtuAndEveryBadReadingRejected) {
  test::PtyPair cable;
  test::KellerTransmitter transmitter(cable.device_end());
  std::string warning;
  std::string error;
  auto link = hal_linux::ModbusLink::open(rtu_bus(cable.glider_end()), warning, error);
  CHECK(link != nullptr);
  ManualClock clock;
  hal_linux::KellerDepthSensor sensor(*link, hal_linux::KellerConfig{}, clock);

  transmitter.set(1.01325f + 2.0f, 11.25f);  // 2 bar of water
  link->begin_cycle();
  hal::DepthSample sample = sensor.read();
  CHECK_TRUE(sample.valid);
  DOUBLES_EQUAL(2e5 / (1025.0 * 9.80665), sample.depth_m, 1e-4);
  DOUBLES_EQUAL(11.25, sensor.last_temperature_c(), 0.0);
  CHECK_EQUAL(7, sample.time_us);

  transmitter.set(std::numeric_limits<float>::quiet_NaN(), 11.0f);  // channel error
  link->begin_cycle();
  CHECK_FALSE(sensor.read().valid);
  transmitter.set(std::numeric_limits<float>::infinity(), 11.0f);  // overflow
  link->begin_cycle();
  CHECK_FALSE(sensor.read().valid);
  CHECK_EQUAL(2u, sensor.stats().channel_errors);
  transmitter.set(45.0f, 11.0f);  // beyond the 30 bar range
  link->begin_cycle();
  CHECK_FALSE(sensor.read().valid);
  transmitter.set(2.0f, 200.0f);  // a temperature no water has: a broken sensor
  link->begin_cycle();
  CHECK_FALSE(sensor.read().valid);
  CHECK_EQUAL(2u, sensor.stats().out_of_range);

  transmitter.stop();  // the transmitter stops answering
  link->begin_cycle();
  CHECK_FALSE(sensor.read().valid);
  CHECK_EQUAL(1u, sensor.stats().bus_failures);
}
