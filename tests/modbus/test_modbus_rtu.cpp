// SPDX-License-Identifier: Apache-2.0
// The driver against the actuator simulator over Modbus RTU on a socat pty
// pair (the glider's end and the device's end of an RS-485 bus).
#include <CppUTest/TestHarness.h>

#include "child_process.hpp"
#include "modbus_fixture.hpp"

using namespace glider;
using glider::test::DriverUnderTest;
using glider::test::PtyPair;
using glider::test::Simulator;

TEST_GROUP(ModbusRtu){};

TEST(ModbusRtu, MovesAndReadsBackAndRs485OnAPtyIsOnlyAWarning) {
  PtyPair bus;
  Simulator sim({"--rtu", bus.device_end()});
  DriverUnderTest d("--rtu", bus.glider_end());
  CHECK(d.warning.find("RS-485 mode not available") != std::string::npos);
  CHECK(d.pump->identify().recognised);
  CHECK(d.pump->command(75.0));
  CHECK(d.slide->command(-0.4));
  CHECK(test::settles_at(d, *d.pump, 75.0));
  CHECK(test::settles_at(d, *d.slide, -0.4));
}

TEST(ModbusRtu, OccasionalCrcErrorsAreRetried) {
  PtyPair bus;
  Simulator sim({"--rtu", bus.device_end(), "--fault", "noise:2"});
  DriverUnderTest d("--rtu", bus.glider_end());
  for (int i = 0; i < 6; ++i) CHECK_FALSE(d.cycle_read(*d.pump).fault);
  CHECK(d.link->stats().attempts > d.link->stats().transactions);
}

TEST(ModbusRtu, CrcErrorsEveryTimeAreAFault) {
  PtyPair bus;
  Simulator sim({"--rtu", bus.device_end(), "--fault", "noise:1"});
  DriverUnderTest d("--rtu", bus.glider_end());
  const hal::ActuatorReading r = d.cycle_read(*d.pump);
  CHECK_FALSE(r.valid);
  CHECK(r.fault);
  STRCMP_EQUAL("Invalid CRC", d.link->last_error());
}

TEST(ModbusRtu, ExceptionRepliesAreAFault) {
  PtyPair bus;
  Simulator sim({"--rtu", bus.device_end(), "--fault", "exception:1"});
  DriverUnderTest d("--rtu", bus.glider_end());
  CHECK(d.cycle_read(*d.slide).fault);
  STRCMP_EQUAL("Slave device or server failure", d.link->last_error());
}

TEST(ModbusRtu, NobodyOnTheBusIsAFault) {
  PtyPair bus;  // socat holds the other end; nothing answers on it
  DriverUnderTest d("--rtu", bus.glider_end());
  const hal::ActuatorReading r = d.cycle_read(*d.pump);
  CHECK_FALSE(r.valid);
  CHECK(r.fault);
  // Timeouts, each followed by a wait for a late reply, until the budget ends.
  CHECK(d.link->stats().attempts >= 1u);
  CHECK_EQUAL(1u, d.link->stats().budget_refusals);
}

TEST(ModbusRtu, ADeviceThatStopsAnsweringMidMoveIsAFault) {
  PtyPair bus;
  Simulator sim({"--rtu", bus.device_end(), "--fault", "silent:3"});
  DriverUnderTest d("--rtu", bus.glider_end());
  CHECK(d.pump->command(-200.0));
  CHECK_FALSE(d.cycle_read(*d.pump).fault);
  CHECK_FALSE(d.cycle_read(*d.pump).fault);
  CHECK(d.cycle_read(*d.pump).fault);
}

TEST(ModbusRtu, LateRepliesAreAFaultAndNeverTakenForTheNextAnswer) {
  PtyPair bus;
  Simulator sim({"--rtu", bus.device_end(), "--fault", "slow:150"});  // response timeout 100 ms
  DriverUnderTest d("--rtu", bus.glider_end());
  // Same slave, function and length: without draining, a late pump reply
  // would pass for the slide's position.
  CHECK(d.cycle_read(*d.pump).fault);
  CHECK(d.cycle_read(*d.slide).fault);
  CHECK(d.cycle_read(*d.pump).fault);
}
